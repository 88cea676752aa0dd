#include "stylos/core/io/PointFileSummary.h"

#include <algorithm>

namespace stylos::core::io {

Result<PointFileSummary> summarizePointFile(const std::filesystem::path& path, const ReadOptions& options,
                                            ProgressSink* progress)
{
    auto opened = openPointReader(path, options);
    if (!opened) return opened.error();
    PointReader& reader = **opened;

    PointFileSummary summary;
    summary.format = reader.header().format;
    summary.declaredPoints = reader.header().declaredPoints;
    summary.attributes = reader.header().schema.attributeNames();
    summary.fileBytes = reader.fileBytes();

    std::array<double, 3> lo{}, hi{};
    PointBatch batch;
    for (;;) {
        if (progress && progress->isCancelRequested())
            return Error::at(ErrorCode::Cancelled, path.string(), "", "cancelled");
        auto got = reader.read(batch, 1 << 16);
        if (!got) return got.error();
        if (*got == 0) break;
        const double* p = batch.positions.data();
        std::size_t i = 0;
        if (summary.points == 0) {
            lo = hi = {p[0], p[1], p[2]};
        }
        for (; i < *got; ++i, p += 3)
            for (int c = 0; c < 3; ++c) {
                lo[c] = std::min(lo[c], p[c]);
                hi[c] = std::max(hi[c], p[c]);
            }
        summary.points += *got;
        if (progress && reader.fileBytes() > 0)
            progress->update(static_cast<double>(reader.bytesConsumed()) / static_cast<double>(reader.fileBytes()));
    }
    summary.skipped = reader.pointsSkipped();
    summary.missing = reader.pointsMissing();
    summary.declaredPoints = reader.header().declaredPoints; // PTX knows it only now
    summary.scans = reader.scans();
    if (summary.points > 0) {
        summary.min = lo;
        summary.max = hi;
    }
    if (progress) progress->update(1.0);
    return summary;
}

} // namespace stylos::core::io
