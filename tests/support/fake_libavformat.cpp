// A stand-in for a libavformat of another major version (1; elbowsim is
// built for Debian 12's 59): loaded through ELBOWSIM_LIBAVFORMAT by a render
// test, which expects the version check to refuse it before anything else
// is looked up.
extern "C" unsigned avformat_version() { return 1u << 16; }
