#pragma once
// What the libFuzzer harnesses share: one scratch file per process (the readers take paths), reading a
// point file to its end through the CLI's entry (io::openPointReader) with the reader contract checked,
// and putting right the checksums a mutation breaks (E57 page CRCs, .poct section and header XXH64) so
// that inputs reach the parsers behind them. A broken contract aborts (libFuzzer reports it as a crash).
#include "stylos/core/io/PointFileFormat.h"

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <string_view>
#include <vector>

namespace stylos::fuzz {

/**
 * @brief Writes @p size bytes to this process's scratch file "input.EXT" (in /dev/shm when writable,
 *        else $TMPDIR, else /tmp; one folder per process, removed at exit) and returns its path.
 */
std::filesystem::path writeScratch(const std::uint8_t* data, std::size_t size, std::string_view extension);

/** @brief The scratch folder itself (for a project's relative paths). */
const std::filesystem::path& scratchFolder();

/**
 * @brief Opens @p path as stylos-cli does and reads every batch (small ones, to cross batch boundaries),
 *        checking what PointReader promises: a batch's arrays agree with its size and schema, positions
 *        are finite, counts only grow, and an error ends the reading.
 */
void readAllPoints(const std::filesystem::path& path, const core::io::ReadOptions& options = {});

/** @brief @p data with the CRC-32C of every whole 1024-byte E57 page recomputed. */
std::vector<std::uint8_t> withE57Checksums(const std::uint8_t* data, std::size_t size);

/**
 * @brief @p data with the XXH64 of every .poct section whose range lies inside the data recomputed, then
 *        the header checksum (when the header's own fields give its size and it fits).
 */
std::vector<std::uint8_t> withPoctChecksums(const std::uint8_t* data, std::size_t size);

/** @brief Prints "stylos-fuzz: contract broken: WHAT" and aborts. */
[[noreturn]] void broken(const char* what);

} // namespace stylos::fuzz
