#pragma once
// What the -DSHADOWLAB_SANITIZE build needs from code that makes GL contexts (a no-op elsewhere).

namespace shadowlab::gl {

// Under AddressSanitizer: keeps every library loaded now (the GL driver the context has just
// loaded, libLLVM, ...) mapped until the process ends. Call it once a context exists. Mesa
// unloads its driver at eglTerminate / display close, and LeakSanitizer, which reports at the very
// end, can then no longer name the module of the driver's own leaks ("<unknown module>"), so
// tests/sanitize/lsan.supp, which names only Mesa's libraries, could not suppress them (measured:
// every EGL render test failed on the same 240 bytes that way).
void keepLoadedLibrariesMappedForLeakReports();

}  // namespace shadowlab::gl
