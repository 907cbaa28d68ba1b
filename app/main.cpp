#include "commands.h"

#include <CLI/CLI.hpp>

#if defined(__GLIBC__)
#include <malloc.h>
#endif

int main(int argc, char** argv) {
#if defined(__GLIBC__)
    // Blocks of 1 MiB and more (decoded images, mesh arrays, and on software GL every texture:
    // llvmpipe keeps a 4096^2 shadow map as 64 MB of host memory) are mmapped and go back to the
    // system when freed. glibc's default threshold follows the largest block freed (up to 32 MiB),
    // so after one 2048^2 map was freed the next ones came from the heap and fragmented it: the
    // soak's resident memory crept +8.7% in six cycles with the heap in use identical each cycle;
    // with the threshold fixed, +0.00% (plane-box, 1260 frames, single-threaded llvmpipe).
    // Nothing of that size is allocated per frame, so the mmap calls cost nothing measurable.
    mallopt(M_MMAP_THRESHOLD, 1 << 20);
#endif
    CLI::App app{"shadowlab: real-time shadow mapping of large glTF scenes (SSM, PSM, LiSPSM)", "shadowlab"};
    app.require_subcommand(0, 1);
    shadowlab::app::addInfoCommand(app);
    shadowlab::app::addRenderCommand(app);
    shadowlab::app::addStressCommand(app);
    shadowlab::app::addGenerateCommand(app);
    shadowlab::app::addSettingsCommand(app);
    shadowlab::app::addSoakCommand(app);
    shadowlab::app::addBenchCommand(app);
    shadowlab::app::addViewerOptions(app);
    CLI11_PARSE(app, argc, argv);
    return 0;
}
