#include "FramedReader.h"

namespace stylos::core::io {

FramedReader::FramedReader(std::unique_ptr<PointReader> inner, const ImportFrame& frame)
    : PointReader(inner->path(), inner->fileBytes()), m_inner(std::move(inner)), m_frame(frame)
{
    follow();
}

Result<std::size_t> FramedReader::read(PointBatch& batch, std::size_t maxPoints)
{
    auto got = m_inner->read(batch, maxPoints);
    follow();
    if (!got) return got;
    m_frame.applyToPositions(batch.positions.data(), batch.positions.size() / 3);
    m_frame.applyToNormals(batch.normals.data(), batch.normals.size() / 3);
    return got;
}

void FramedReader::follow()
{
    m_header = m_inner->header();
    if (m_header.declaredBounds) {
        auto& b = *m_header.declaredBounds;
        std::array<double, 3> min{b[0], b[1], b[2]}, max{b[3], b[4], b[5]};
        m_frame.applyToBounds(min, max);
        b = {min[0], min[1], min[2], max[0], max[1], max[2]};
    }
    m_pointsRead = m_inner->pointsRead();
    m_pointsSkipped = m_inner->pointsSkipped();
    m_pointsMissing = m_inner->pointsMissing();
    m_scans = m_inner->scans();
}

} // namespace stylos::core::io
