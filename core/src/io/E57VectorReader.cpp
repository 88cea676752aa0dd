#include "stylos/core/io/E57VectorReader.h"

#include <algorithm>
#include <cassert>
#include <cstring>
#include <limits>

namespace stylos::core::io {

namespace {

constexpr std::size_t kSectionHeaderBytes = 32;
constexpr std::size_t kPadding = 16;

template <typename T>
T loadLe(const unsigned char* p)
{
    T v;
    std::memcpy(&v, p, sizeof v);
    return v;
}

} // namespace

Error E57VectorReader::fail(std::uint64_t byte, const std::string& problem) const
{
    return Error::at(ErrorCode::Malformed, m_file->path().string(), "byte " + std::to_string(byte),
                     m_label + ": " + problem);
}

Result<E57VectorReader> E57VectorReader::open(E57PagedFile& file, const E57Scan& scan, std::vector<int> wanted,
                                              std::string label)
{
    E57VectorReader r(file, std::move(label));
    const std::uint64_t at = scan.sectionOffset;
    auto bad = [&](const std::string& problem) {
        return r.fail(at, "invalid compressed-vector section header: " + problem);
    };
    if (at >= file.size() || !E57PagedFile::isPayload(at)) return bad("its offset lies outside the file's data");
    unsigned char h[kSectionHeaderBytes];
    if (auto s = file.read(at, sizeof h, h, r.m_label + "'s compressed-vector section header"); !s) return s.error();
    const std::uint64_t sectionLength = loadLe<std::uint64_t>(h + 8);
    const std::uint64_t dataOffset = loadLe<std::uint64_t>(h + 16);
    const std::uint64_t indexOffset = loadLe<std::uint64_t>(h + 24);
    if (h[0] != 1) return bad("section id " + std::to_string(h[0]) + ", expected 1");
    const std::uint64_t start = E57PagedFile::toLogical(at);
    const std::uint64_t fileLogical = file.size() / E57PagedFile::PageBytes * E57PagedFile::PayloadBytes;
    if (sectionLength < kSectionHeaderBytes || sectionLength % 4 != 0 || sectionLength > fileLogical - start)
        return bad("section length " + std::to_string(sectionLength) + " is not a multiple of 4 inside the file");
    r.m_sectionEnd = start + sectionLength;
    if (indexOffset >= file.size()) return bad("index offset " + std::to_string(indexOffset) + " lies outside the file");
    if (scan.recordCount > 0 &&
        (dataOffset >= file.size() || !E57PagedFile::isPayload(dataOffset) ||
         E57PagedFile::toLogical(dataOffset) < start + kSectionHeaderBytes ||
         E57PagedFile::toLogical(dataOffset) >= r.m_sectionEnd))
        return bad("data offset " + std::to_string(dataOffset) + " lies outside the section");

    r.m_fieldCount = scan.fields.size();
    r.m_streamOfField.assign(r.m_fieldCount, -1);
    for (int f : wanted) {
        assert(f >= 0 && std::size_t(f) < r.m_fieldCount && "E57VectorReader::open(): wanted field out of range");
        r.m_streamOfField[f] = static_cast<int>(r.m_streams.size());
        Stream s;
        s.field = scan.fields[f];
        s.bits = s.field.bits();
        s.bytes.assign(kPadding, 0);
        r.m_streams.push_back(std::move(s));
    }
    r.m_recordsLeft = scan.recordCount;
    r.m_nextPacket = dataOffset;
    return r;
}

std::uint64_t E57VectorReader::Stream::available() const
{
    if (bits == 0) return std::numeric_limits<std::uint64_t>::max();
    return (std::uint64_t(size) * 8 - bitPos) / bits;
}

void E57VectorReader::Stream::append(const unsigned char* data, std::size_t n)
{
    // Drop the bytes already decoded, keep the partial byte.
    const std::size_t done = static_cast<std::size_t>(bitPos / 8);
    if (done > 0) {
        std::memmove(bytes.data(), bytes.data() + done, size - done);
        size -= done;
        bitPos -= 8 * done;
    }
    bytes.resize(size + n + kPadding);
    std::memcpy(bytes.data() + size, data, n);
    std::memset(bytes.data() + size + n, 0, kPadding);
    size += n;
}

void E57VectorReader::Stream::decode(std::size_t count, double* out)
{
    using T = E57Field::Type;
    if (field.type == T::Float) {
        const unsigned char* p = bytes.data() + bitPos / 8;
        if (field.singlePrecision)
            for (std::size_t i = 0; i < count; ++i) out[i] = loadLe<float>(p + 4 * i);
        else
            for (std::size_t i = 0; i < count; ++i) out[i] = loadLe<double>(p + 8 * i);
        bitPos += std::uint64_t(count) * bits;
        return;
    }
    const double scale = field.type == T::ScaledInteger ? field.scale : 1.0;
    const double offset = field.type == T::ScaledInteger ? field.offset : 0.0;
    const std::uint64_t minimum = std::uint64_t(field.minimum);
    if (bits == 0) {
        std::fill_n(out, count, double(field.minimum) * scale + offset);
        return;
    }
    const std::uint64_t mask = bits == 64 ? ~std::uint64_t(0) : (std::uint64_t(1) << bits) - 1;
    for (std::size_t i = 0; i < count; ++i, bitPos += bits) {
        const unsigned char* p = bytes.data() + bitPos / 8;
        const unsigned shift = static_cast<unsigned>(bitPos % 8);
        std::uint64_t word = loadLe<std::uint64_t>(p) >> shift;
        if (shift + bits > 64) word |= std::uint64_t(p[8]) << (64 - shift);
        const auto raw = static_cast<std::int64_t>((word & mask) + minimum); // wraps like the writer's subtraction
        out[i] = double(raw) * scale + offset;
    }
}

Status E57VectorReader::readPacket()
{
    const std::uint64_t at = m_nextPacket;
    if (!E57PagedFile::isPayload(at) || E57PagedFile::toLogical(at) + 4 > m_sectionEnd)
        return fail(at, "the compressed vector ends after " + std::to_string(m_recordsLeft) +
                            " of its records are still to come (no packet left in its section)");
    unsigned char head[4];
    if (auto s = m_file->read(at, 4, head, m_label + "'s data packet"); !s) return s;
    const std::size_t length = std::size_t(loadLe<std::uint16_t>(head + 2)) + 1;
    if (E57PagedFile::toLogical(at) + length > m_sectionEnd)
        return fail(at, "a packet of " + std::to_string(length) + " bytes runs past the end of its section");
    m_nextPacket = E57PagedFile::advance(at, length);
    if (head[0] == 0 || head[0] == 2) return {}; // index or empty packet
    if (head[0] != 1) return fail(at, "unknown packet type " + std::to_string(head[0]));
    m_packet.resize(length);
    if (auto s = m_file->read(at, length, m_packet.data(), m_label + "'s data packet"); !s) return s;
    if (length < 6) return fail(at, "a data packet of " + std::to_string(length) + " bytes is too short");
    const std::size_t count = loadLe<std::uint16_t>(m_packet.data() + 4);
    if (count != m_fieldCount)
        return fail(at, "a data packet has " + std::to_string(count) + " bytestreams, the prototype " +
                            std::to_string(m_fieldCount) + " fields");
    std::size_t offset = 6 + 2 * count;
    if (offset > length) return fail(at, "a data packet's buffer lengths run past its end");
    for (std::size_t f = 0; f < count; ++f) {
        const std::size_t n = loadLe<std::uint16_t>(m_packet.data() + 6 + 2 * f);
        if (offset + n > length) return fail(at, "a data packet's buffers run past its end");
        if (m_streamOfField[f] >= 0) m_streams[m_streamOfField[f]].append(m_packet.data() + offset, n);
        offset += n;
    }
    return {};
}

Result<std::size_t> E57VectorReader::read(std::size_t maxRecords, std::vector<std::vector<double>>& columns)
{
    const auto target = static_cast<std::size_t>(std::min<std::uint64_t>(maxRecords, m_recordsLeft));
    columns.resize(m_streams.size());
    if (target == 0) {
        for (auto& c : columns) c.clear();
        return std::size_t(0);
    }
    auto ready = [&] {
        std::uint64_t n = target;
        for (const Stream& s : m_streams) n = std::min(n, s.available());
        return n;
    };
    // At least one record in every stream; more arrive only while a packet is needed anyway.
    while (ready() == 0)
        if (auto s = readPacket(); !s) return s.error();
    const auto n = static_cast<std::size_t>(ready());
    for (std::size_t k = 0; k < m_streams.size(); ++k) {
        columns[k].resize(n);
        m_streams[k].decode(n, columns[k].data());
    }
    m_recordsLeft -= n;
    return n;
}

} // namespace stylos::core::io
