#pragma once
/** @file
 * @brief Asks the kernel to back a large, not yet touched buffer with 2 MiB pages (Linux transparent huge
 *        pages in "madvise" mode, Debian's default). On a first touch each 4 KiB page otherwise costs a fault,
 *        and on virtual machines a fault costs microseconds: a 100 MB array fresh from the allocator spends more
 *        time faulting than being written. Only the 2 MiB-aligned middle of the range can be huge.
 * Best effort: errors are ignored and other systems do nothing. Call it after reserving and before the first
 * write (pages already touched stay small). Thread-safety: reentrant.
 */
#include <cstddef>

namespace stylos::core {

void adviseHugePages(const void* data, std::size_t bytes);

} // namespace stylos::core
