// Callgrind's client requests for the study's profiling programs (toi_profile, gjk_profile):
// run under `valgrind --tool=callgrind --instr-atstart=no`, only the code between
// GJKX_PROFILE_START() and GJKX_PROFILE_STOP() is counted. Without valgrind's header they
// do nothing.
#pragma once

#if __has_include(<valgrind/callgrind.h>)
#include <valgrind/callgrind.h>
#define GJKX_PROFILE_START() CALLGRIND_START_INSTRUMENTATION
#define GJKX_PROFILE_STOP() CALLGRIND_STOP_INSTRUMENTATION
#else
#define GJKX_PROFILE_START() ((void)0)
#define GJKX_PROFILE_STOP() ((void)0)
#endif
