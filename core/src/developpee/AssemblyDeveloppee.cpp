#include "stylos/core/developpee/AssemblyDeveloppee.h"

#include "stylos/core/util/SubProgress.h"

#include <cmath>
#include <vector>

namespace stylos::core::developpee {
namespace {

/** The pixel @p world lands in through @p d's map, when within its band; −1 otherwise. */
long long pixelIndex(const Developpee& d, const Eigen::Vector3d& world, double* h = nullptr)
{
    const auto hit = d.map.pixelOf(world);
    if (!hit || !(std::abs(hit->h) <= d.unroll.band)) return -1;
    const int column = int(std::floor(hit->column)), row = int(std::floor(hit->row));
    if (column < 0 || row < 0 || column >= d.map.width() || row >= d.map.height()) return -1;
    if (h) *h = hit->h;
    return (long long)row * d.map.width() + column;
}

} // namespace

std::uint64_t AssemblyDeveloppee::pieceOf(int column, int row) const
{
    const int w = developpee.map.width(), hgt = developpee.map.height();
    if (column < 0 || row < 0 || column >= w || row >= hgt) return 0;
    return pieceAt[std::size_t(row) * std::size_t(w) + std::size_t(column)];
}

Result<AssemblyDeveloppee> computeAssemblyDeveloppee(const cloud::PointCloud& drum,
                                                     const std::vector<AssemblyPiece>& pieces,
                                                     const DeveloppeeOptions& options, ProgressSink* progress)
{
    const std::string source = drum.source.empty() ? "<memory>" : drum.source;
    if (!options.axis)
        return Error::at(ErrorCode::InvalidArgument, source, {}, "the développée of an assembly needs the drum's axis");
    for (const AssemblyPiece& p : pieces)
        if (!p.cloud || p.id == 0) return Error::at(ErrorCode::InvalidArgument, source, {}, "a piece without a cloud or an id");

    // (1) The drum alone: its pixel size and cut, on the whole turn (a drum broken over half of it keeps the room
    // where its pieces dock).
    SubProgress first(progress, 0.0, 0.45);
    DeveloppeeOptions wholeTurn = options;
    wholeTurn.cropToPoints = false;
    auto alone = computeDeveloppee(drum, wholeTurn, progress ? &first : nullptr);
    if (!alone) return alone.error();
    const int width = alone->map.width(), height = alone->map.height();

    // (2) The pieces' footprints, grown by one pixel (the first piece's where two meet).
    std::vector<std::uint64_t> footprint(std::size_t(width) * std::size_t(height), 0);
    for (const AssemblyPiece& p : pieces)
        for (std::size_t i = 0; i < p.cloud->size(); ++i) {
            const long long at = pixelIndex(*alone, p.toDrum * p.cloud->world(i));
            if (at < 0) continue;
            const int column = int(at % width), row = int(at / width);
            for (int dr = -1; dr <= 1; ++dr)
                for (int dc = -1; dc <= 1; ++dc) {
                    const int c = column + dc, r = row + dr;
                    if (c >= 0 && r >= 0 && c < width && r < height && !footprint[std::size_t(r) * width + c])
                        footprint[std::size_t(r) * width + c] = p.id;
                }
        }
    if (progress && progress->isCancelRequested()) return Error{ErrorCode::Cancelled, source + ": cancelled"};

    // (3) One cloud: the drum off the footprints, and every piece; unrolled on the drum's grid.
    cloud::PointCloud combined;
    combined.origin = drum.origin;
    combined.spacing = drum.spacing;
    combined.source = drum.source;
    for (std::size_t i = 0; i < drum.size(); ++i) {
        const long long at = pixelIndex(*alone, drum.world(i));
        if (at >= 0 && footprint[std::size_t(at)]) continue;
        combined.addWorld(drum.world(i));
    }
    for (const AssemblyPiece& p : pieces) // their points near the drum's surface (a piece's far faces are not on it)
        for (std::size_t i = 0; i < p.cloud->size(); ++i) {
            const Eigen::Vector3d q = p.toDrum * p.cloud->world(i);
            if (pixelIndex(*alone, q) >= 0) combined.addWorld(q);
        }
    DeveloppeeOptions same = options;
    same.pixelSize = alone->unroll.pixelSize;
    same.cutAngle = alone->unroll.cutAngle;
    SubProgress second(progress, 0.45, 0.95);
    auto together = computeDeveloppee(combined, same, progress ? &second : nullptr);
    if (!together) return together.error();

    // (4) Each pixel's piece: the outermost piece point there.
    AssemblyDeveloppee result{std::move(together).value(), {}};
    const std::size_t pixels = std::size_t(result.developpee.map.width()) * std::size_t(result.developpee.map.height());
    result.pieceAt.assign(pixels, 0);
    std::vector<double> outermost(pixels, -1e300);
    for (const AssemblyPiece& p : pieces)
        for (std::size_t i = 0; i < p.cloud->size(); ++i) {
            double h = 0.0;
            const long long at = pixelIndex(result.developpee, p.toDrum * p.cloud->world(i), &h);
            if (at < 0 || h <= outermost[std::size_t(at)]) continue;
            outermost[std::size_t(at)] = h;
            result.pieceAt[std::size_t(at)] = p.id;
        }
    // The footprint's pixels no piece point reached (between sparse points, or filled): its piece too.
    const Developpee& d = result.developpee;
    for (int row = 0; row < d.map.height(); ++row)
        for (int column = 0; column < d.map.width(); ++column) {
            std::uint64_t& owner = result.pieceAt[std::size_t(row) * d.map.width() + column];
            if (owner != 0 || !d.field.hasHeight(column, row)) continue;
            const long long at = pixelIndex(*alone, d.map.worldAtPixel(column + 0.5, row + 0.5, 0.0));
            if (at >= 0) owner = footprint[std::size_t(at)];
        }
    if (progress) progress->update(1.0);
    return result;
}

} // namespace stylos::core::developpee
