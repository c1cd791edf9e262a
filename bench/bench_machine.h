// bench_machine.h — what the benchmark reports record about the machine (Linux /proc)
// and the build (macros from bench/CMakeLists.txt, "unknown" without them).
#ifndef LH_BENCH_MACHINE_H
#define LH_BENCH_MACHINE_H

#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <string>

#ifndef LH_BENCH_C_COMPILER
#define LH_BENCH_C_COMPILER "unknown"
#endif
#ifndef LH_BENCH_CXX_COMPILER
#define LH_BENCH_CXX_COMPILER "unknown"
#endif
#ifndef LH_BENCH_BUILD_TYPE
#define LH_BENCH_BUILD_TYPE "unknown"
#endif
#ifndef LH_BENCH_C_FLAGS
#define LH_BENCH_C_FLAGS ""
#endif
#ifndef LH_BENCH_CXX_FLAGS
#define LH_BENCH_CXX_FLAGS ""
#endif

// The CPU's model name, or "unknown".
inline std::string cpu_model()
{
    std::ifstream f("/proc/cpuinfo");
    std::string line;
    while (std::getline(f, line))
        if (line.rfind("model name", 0) == 0) {
            auto p = line.find(':');
            if (p != std::string::npos) {
                std::string s = line.substr(p + 1);
                s.erase(0, s.find_first_not_of(" \t"));
                return s;
            }
        }
    return "unknown";
}

// Total memory as "23.5 GiB", or "unknown".
inline std::string mem_total()
{
    std::ifstream f("/proc/meminfo");
    std::string line;
    while (std::getline(f, line))
        if (line.rfind("MemTotal:", 0) == 0) {
            long kb = std::atol(line.c_str() + 9);
            char b[32];
            std::snprintf(b, sizeof b, "%.1f GiB", double(kb) / (1024.0 * 1024.0));
            return b;
        }
    return "unknown";
}

#endif
