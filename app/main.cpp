#include "commands.h"

#if defined(__GLIBC__)
#include <cstdlib>
#include <malloc.h>
#endif

int main(int argc, char** argv) {
#if defined(__GLIBC__)
    // glibc moves its mmap threshold up to the largest block freed (to 32 MiB), after which freed
    // blocks of that size are kept in the heap and fragment it: llvmpipe keeps every texture in host
    // memory, and after a 2048^2 map (16 MB) was freed the soak's resident memory crept +8.7% in six
    // cycles with the heap in use identical each cycle. Any fixed threshold stops the moving (+0.00%
    // at 1, 4, 8 and 32 MiB, plane-box, 1260 frames); 32 MiB, the top of glibc's range, keeps
    // decoded textures in the heap as before (Sponza render, whole process: CPU 0.99x, wall 1.00x;
    // at 1 MiB every texture was mmapped: CPU 1.13x, wall 1.09x).
    if (!std::getenv("MALLOC_MMAP_THRESHOLD_")) mallopt(M_MMAP_THRESHOLD, 32 << 20);  // an explicit tuning wins
#endif
    return shadowlab::app::runCommandLine(argc, argv);
}
