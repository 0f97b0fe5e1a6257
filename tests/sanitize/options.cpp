// Default sanitizer options, linked into every executable of the sanitized
// build (TSIS_SANITIZE=ON), so that ctest, the tsis binary the CLI tests start
// and a test run by hand all read the same suppressions. ASAN_OPTIONS,
// LSAN_OPTIONS and UBSAN_OPTIONS still override them.

#ifndef TSIS_SANITIZE_DIR
#error "TSIS_SANITIZE_DIR names tests/sanitize"
#endif

extern "C" {

// Why each library is suppressed: tests/sanitize/lsan.supp.
const char* __lsan_default_options() {
    return "suppressions=" TSIS_SANITIZE_DIR "/lsan.supp:print_suppressions=0";
}

const char* __asan_default_options() {
    return "suppressions=" TSIS_SANITIZE_DIR "/asan.supp:detect_leaks=1:abort_on_error=0";
}

// A finding aborts (the code is built with -fno-sanitize-recover=undefined);
// the stack says where.
const char* __ubsan_default_options() {
    return "print_stacktrace=1:halt_on_error=1";
}
}
