#pragma once
/** @file
 * @brief Streams the records of one E57 compressed vector (ASTM E2807 §9): its binary section header,
 *        then data packets (index and empty packets skipped), each holding one buffer per prototype
 *        field; every field's buffers form one continuous bytestream, decoded with the bitpack codec —
 *        Float as little-endian 4- or 8-byte values, Integer and ScaledInteger as (value − minimum) in
 *        the field's bit width, packed from the least significant bit. Only the chosen fields are kept;
 *        the others' buffers are dropped as packets arrive, so memory holds about one packet per field.
 *        Not thread-safe.
 */
#include "stylos/core/io/E57PagedFile.h"
#include "stylos/core/io/E57Structure.h"

#include <cstdint>
#include <string>
#include <vector>

namespace stylos::core::io {

class E57VectorReader {
public:
    /**
     * @brief Reads and checks the section header of @p scan's points (section id 1, lengths and offsets
     *        inside the file). @p wanted lists the prototype fields to decode, in the order read() fills its
     *        columns. @p label names the scan in messages ("scan 0 (\"bunny\")"). Errors: Malformed
     *        "invalid compressed-vector section header" naming the byte and the field, the paged file's.
     */
    static Result<E57VectorReader> open(E57PagedFile& file, const E57Scan& scan, std::vector<int> wanted,
                                        std::string label);

    /**
     * @brief Decodes the next records (at most @p maxRecords) into @p columns (one per wanted field,
     *        resized to the count). Returns 0 once every record is read. Errors: Malformed for a packet
     *        of an unknown type, a packet outside the section, a bytestream count that differs from the
     *        prototype's, buffers longer than their packet, or a section that ends before its records.
     */
    Result<std::size_t> read(std::size_t maxRecords, std::vector<std::vector<double>>& columns);

    std::uint64_t recordsLeft() const { return m_recordsLeft; }
    /** Physical offset of the next packet, for progress. */
    std::uint64_t nextPacket() const { return m_nextPacket; }

private:
    struct Stream {
        E57Field field;
        unsigned bits = 0;
        std::vector<unsigned char> bytes; ///< undecoded bytes, then 16 zero bytes of padding
        std::size_t size = 0;             ///< undecoded bytes (without the padding)
        std::uint64_t bitPos = 0;         ///< next bit to decode within bytes
        std::uint64_t available() const;
        void append(const unsigned char* data, std::size_t n);
        void decode(std::size_t count, double* out);
    };

    E57VectorReader(E57PagedFile& file, std::string label) : m_file(&file), m_label(std::move(label)) {}
    Status readPacket();
    Error fail(std::uint64_t byte, const std::string& problem) const;

    E57PagedFile* m_file;
    std::string m_label;
    std::size_t m_fieldCount = 0;       ///< bytestreams per data packet (the prototype's fields)
    std::vector<int> m_streamOfField;   ///< prototype field → index in m_streams, or -1 (dropped)
    std::vector<Stream> m_streams;      ///< the wanted fields, in the order of the columns
    std::uint64_t m_recordsLeft = 0;
    std::uint64_t m_nextPacket = 0;     ///< physical offset
    std::uint64_t m_sectionEnd = 0;     ///< logical offset just past the section
    std::vector<unsigned char> m_packet;
};

} // namespace stylos::core::io
