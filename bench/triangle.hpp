// Shewchuk's Triangle (Debian's libtriangle-dev, non-free) for the benchmarks that compare
// with it, where CMake found it (RIDT_WITH_TRIANGLE): its header wants these macros first.
#pragma once

#ifdef RIDT_WITH_TRIANGLE
#define REAL double
#define VOID void
#define ANSI_DECLARATORS
extern "C" {
#include <triangle.h>
}
#endif
