// Linked into every executable of a sanitizer build (ENSIL_SANITIZE), nowhere else.
//
// LeakSanitizer checks for leaks when the process ends, after libraries have been unloaded:
// Mesa's GLX unloads its driver (swrast_dri.so, with llvmpipe and LLVM) when Qt closes the X
// display. Blocks the driver still holds through its globals then look leaked, since nothing
// reachable points at them any more, and their allocation stacks end in "<unknown module>", so
// no suppression can name them. A process of a sanitizer build therefore never unloads a
// library: this dlclose, exported from the executable, comes before libc's in the lookup order
// of every library that calls it, and does nothing. Leaks in ensil's own code are still found.
extern "C" int dlclose(void* /*handle*/) { return 0; }
