// Internal: the process's memory as the kernel counts it, for the memory guard and the report.
#pragma once

#include <cstddef>

namespace vorocrust {

// Bytes resident now (Linux's /proc/self/statm); 0 where the system does not say.
std::size_t resident_bytes() noexcept;

// The most bytes resident at once so far (getrusage's ru_maxrss); 0 where the system does not say.
std::size_t peak_resident_bytes() noexcept;

}  // namespace vorocrust
