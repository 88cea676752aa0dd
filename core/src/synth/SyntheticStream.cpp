#include "stylos/core/synth/SyntheticStream.h"

#include "stylos/core/synth/DrumShape.h"

#include <algorithm>
#include <array>
#include <cassert>
#include <cmath>
#include <numbers>
#include <string>
#include <vector>

namespace stylos::core::synth {
namespace {

constexpr double kTwoPi = 2.0 * std::numbers::pi;
constexpr std::uint64_t kGolden = 0x9E3779B97F4A7C15ull;
constexpr int kPlainSectors = 64;        ///< angular sectors of a plain cylinder (keeps angles small)
constexpr int kAreaTable = 256;          ///< entries of the inverse swept-area table of a flute
constexpr std::uint64_t kBytesPerPoint = 36; ///< 3 doubles + 3 floats, as a binary PLY would hold them

/** SplitMix64's output function: output n of the generator seeded with s is mix(s + (n + 1)·golden). */
inline std::uint64_t mix(std::uint64_t z)
{
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
    return z ^ (z >> 31);
}

/** Uniform in [0, 1) from the top 53 bits. */
inline double unit(std::uint64_t bits) { return static_cast<double>(bits >> 11) * 0x1.0p-53; }
/** Uniform in [0, 1) from the high 32 bits (resolution 2.3e-10: below a nanometre on a drum). */
inline double unitHigh(std::uint64_t bits) { return static_cast<double>(bits >> 32) * 0x1.0p-32; }
/** Uniform in [0, 1) from the low 32 bits. */
inline double unitLow(std::uint64_t bits) { return static_cast<double>(bits & 0xFFFFFFFFull) * 0x1.0p-32; }

/**
 * sin and cos of |x| ≤ π/2 + 0.007: the nearest multiple of 1/64 rad from a table (libm, once), the
 * remainder (|r| ≤ 1/128) by short Taylor polynomials (truncation < 1e-18), then the angle-sum formulas:
 * no libm call per point. Every angle the sampler needs is within range (flute arcs: |ψ| ≤ β < π/2;
 * fillets: at most a third of a turn wide, measured from their centre).
 */
class SinCosTable {
public:
    SinCosTable()
    {
        for (int j = -kSteps; j <= kSteps; ++j) {
            m_sin[static_cast<std::size_t>(j + kSteps)] = std::sin(j / 64.0);
            m_cos[static_cast<std::size_t>(j + kSteps)] = std::cos(j / 64.0);
        }
    }

    void operator()(double x, double& s, double& c) const
    {
        assert(std::fabs(x) < kSteps / 64.0 && "SinCosTable::operator(): angle out of range");
        const int j = static_cast<int>(x * 64.0 + (kSteps + 0.5)) - kSteps; // nearest, x ≥ −kSteps/64
        const double r = x - j / 64.0, r2 = r * r;
        const double sr = r + r * r2 * (-1.0 / 6 + r2 * (1.0 / 120 + r2 * (-1.0 / 5040)));
        const double cr = 1.0 + r2 * (-0.5 + r2 * (1.0 / 24 + r2 * (-1.0 / 720)));
        const std::size_t k = static_cast<std::size_t>(j + kSteps);
        s = m_sin[k] * cr + m_cos[k] * sr;
        c = m_cos[k] * cr - m_sin[k] * sr;
    }

private:
    static constexpr int kSteps = 101; ///< 101/64 > π/2
    std::array<double, 2 * kSteps + 1> m_sin{}, m_cos{};
};

Error invalid(const std::string& problem)
{
    return Error::at(ErrorCode::InvalidArgument, "synthetic-drum", "", problem);
}

/**
 * The geometry of one period of the outline (a flute arc then a fillet arc, centred on the flute's
 * azimuth) and the maps from uniform variates to points on the lateral surface and the bed faces.
 */
class DrumSampler {
public:
    static Result<DrumSampler> make(const SyntheticStreamOptions& o)
    {
        if (!(o.radius > 0) || !(o.height > 0) || !std::isfinite(o.radius) || !std::isfinite(o.height))
            return invalid("radius and height must be positive numbers of metres");
        if (!(o.noise >= 0) || !std::isfinite(o.noise)) return invalid("noise must be zero or a positive number of metres");
        DrumParameters p;
        p.radius = o.radius;
        p.height = o.height;
        p.grooves = o.grooves;
        p.grooveDepth = o.grooveDepth;
        p.filletFraction = o.filletFraction;
        if (const auto problem = p.problem(); !problem.empty()) return invalid(problem);
        DrumSampler s(o);
        if (s.m_grooved && !(s.m_arcCentre * std::cos(s.m_beta) > s.m_arcRadius))
            return invalid("flutes so deep that the outline is not star-shaped from the axis");
        return s;
    }

    SyntheticDrumAreas areas() const
    {
        return {m_totalLength * m_height, m_totalArea, m_totalLength};
    }

    // Both maps are branch-free (a 0/1 factor selects the flute or the fillet arc: exact, since
    // g·x + (1 − g)·y is x or y): whether a random point falls on a flute or a fillet is unpredictable,
    // and mispredicted branches would serialise the work of consecutive points.

    /** Point at fraction @p u01 of the outline's length and @p z01 of the height. */
    void lateral(double u01, double z01, double* p, float* n) const
    {
        const double u = u01 * m_totalLength;
        const int k = std::min(m_sectors - 1, static_cast<int>(u * m_invPeriodLength));
        const double s = u - k * m_periodLength;
        const int fillet = s >= m_grooveLength;
        const double g = 1 - fillet;
        const double t = g * (s * m_invArcRadius - m_beta) + (1 - g) * ((s - m_grooveLength) * m_invRadius - m_filletHalf);
        double sn, cs;
        m_sinCos(t, sn, cs);
        const std::size_t entry = 2 * static_cast<std::size_t>(k) + static_cast<std::size_t>(fillet);
        arcPoint(entry, g, sn, cs, 1.0, p);
        // Normal (cos t, −sin t) on a flute, (cos t, sin t) on a fillet, rotated likewise.
        const double nx = cs, ny = (1 - 2 * g) * sn, rc = m_rotation[2 * entry], rs = m_rotation[2 * entry + 1];
        p[2] = z01 * m_height;
        n[0] = static_cast<float>(rc * nx - rs * ny);
        n[1] = static_cast<float>(rs * nx + rc * ny);
        n[2] = 0.0f;
    }

    /** Point of a bed face at fraction @p w01 of its swept area (the fan's angle) and @p v01 of r². */
    void bed(double w01, double v01, bool top, double* p, float* n) const
    {
        const double w = w01 * m_totalArea;
        const int k = std::min(m_sectors - 1, static_cast<int>(w * m_invPeriodArea));
        const double s = w - k * m_periodArea;
        const int fillet = s >= m_grooveArea;
        const double g = 1 - fillet;
        // On a flute: ψ where the swept area is s, from the table, then one Newton step (below).
        const double at = s * m_tablePerArea;
        const int m = std::min(kAreaTable - 1, static_cast<int>(at));
        const double psi0 = m_psiAtArea[m] + (at - m) * (m_psiAtArea[m + 1] - m_psiAtArea[m]);
        const double t = g * psi0 + (1 - g) * ((s - m_grooveArea) * m_invHalfRadius2 - m_filletHalf);
        double s0, c0;
        m_sinCos(t, s0, c0);
        const double a = m_arcRadius, c = m_arcCentre;
        const double f0 = 0.5 * (a * c * (s0 + m_sinBeta) - a * a * (t + m_beta));
        const double slope = 0.5 * (a * c * c0 - a * a) + (1 - g); // > 0; its value is unused on fillets
        const double delta = g * (s - f0) / slope;                   // |δ| < 1e-5 on flutes, 0 on fillets
        // sin and cos at ψ0 + δ to second order (the error, ~δ³, is below 1e-16).
        const double sn = s0 + delta * c0 - 0.5 * delta * delta * s0;
        const double cs = c0 - delta * s0 - 0.5 * delta * delta * c0;
        arcPoint(2 * static_cast<std::size_t>(k) + static_cast<std::size_t>(fillet), g, sn, cs, std::sqrt(v01), p);
        p[2] = top * m_height;
        n[0] = 0.0f;
        n[1] = 0.0f;
        n[2] = static_cast<float>(2 * top - 1);
    }

private:
    explicit DrumSampler(const SyntheticStreamOptions& o) : m_radius(o.radius), m_height(o.height)
    {
        m_grooved = o.grooves > 0;
        m_sectors = m_grooved ? o.grooves : kPlainSectors;
        const double pitch = kTwoPi / m_sectors;
        const double halfWidth = m_grooved ? 0.5 * pitch * (1.0 - o.filletFraction) : 0.0;
        m_filletHalf = 0.5 * pitch - halfWidth;
        if (m_grooved) {
            // The arc through the flute's edges (radius R, azimuth ±halfWidth) and its bottom (R − d, 0),
            // as DrumShape: centre on the mid-line at distance c from the axis; β its half-angle seen from
            // the centre. Points: (c − a cos ψ, a sin ψ), ψ ∈ [−β, β]; outward normal (cos ψ, −sin ψ).
            const double r = o.radius, d = o.grooveDepth;
            m_arcCentre = ((r - d) * (r - d) - r * r) / (2.0 * (r - d - r * std::cos(halfWidth)));
            m_arcRadius = m_arcCentre - (r - d);
            m_beta = std::acos(std::clamp((m_arcCentre - r * std::cos(halfWidth)) / m_arcRadius, -1.0, 1.0));
            m_sinBeta = std::sin(m_beta);
            m_grooveLength = 2.0 * m_arcRadius * m_beta;
            m_grooveArea = sweptArea(m_beta);
        }
        m_periodLength = m_grooveLength + 2.0 * m_filletHalf * m_radius;
        m_periodArea = m_grooveArea + m_filletHalf * m_radius * m_radius;
        m_totalLength = m_sectors * m_periodLength;
        m_totalArea = m_sectors * m_periodArea;
        m_invRadius = 1.0 / m_radius;
        m_invHalfRadius2 = 2.0 / (m_radius * m_radius);
        m_invArcRadius = m_grooved ? 1.0 / m_arcRadius : 0.0;
        m_invPeriodLength = 1.0 / m_periodLength;
        m_invPeriodArea = 1.0 / m_periodArea;
        m_tablePerArea = m_grooved ? kAreaTable / m_grooveArea : 0.0;
        for (int k = 0; k < m_sectors; ++k)
            for (const double theta : {k * pitch, (k + 0.5) * pitch}) {
                m_rotation.push_back(std::cos(theta));
                m_rotation.push_back(std::sin(theta));
            }
        buildAreaTable();
    }

    /** Area swept from the axis over the flute arc from −β to ψ (closed form: ½∫ p × p′ dψ). */
    double sweptArea(double psi) const
    {
        const double a = m_arcRadius, c = m_arcCentre;
        return 0.5 * (a * c * (std::sin(psi) + std::sin(m_beta)) - a * a * (psi + m_beta));
    }

    void buildAreaTable()
    {
        m_psiAtArea.assign(kAreaTable + 1, 0.0); // zeros for a plain cylinder (never selected)
        if (!m_grooved) return;
        for (int m = 0; m <= kAreaTable; ++m) {
            const double target = m_grooveArea * m / kAreaTable;
            double lo = -m_beta, hi = m_beta;
            for (int it = 0; it < 80; ++it) {
                const double mid = 0.5 * (lo + hi);
                (sweptArea(mid) < target ? lo : hi) = mid;
            }
            m_psiAtArea[static_cast<std::size_t>(m)] = 0.5 * (lo + hi);
        }
    }

    /**
     * x and y, scaled by @p scale, of the point at angle t (sin @p sn, cos @p cs) on a flute arc (g = 1:
     * (c − a cos t, a sin t)) or a fillet arc (g = 0: R (cos t, sin t)), in the frame of its centre,
     * rotated by table entry @p entry.
     */
    void arcPoint(std::size_t entry, double g, double sn, double cs, double scale, double* p) const
    {
        const double rho = g * m_arcRadius + (1 - g) * m_radius, sigma = 1 - 2 * g;
        const double x = g * m_arcCentre + sigma * rho * cs, y = rho * sn;
        const double rc = m_rotation[2 * entry], rs = m_rotation[2 * entry + 1];
        p[0] = scale * (rc * x - rs * y);
        p[1] = scale * (rs * x + rc * y);
    }

    double m_radius, m_height;
    bool m_grooved = false;
    int m_sectors = 0;
    double m_filletHalf = 0;      ///< half the angular width of a fillet
    double m_arcCentre = 0, m_arcRadius = 0, m_beta = 0;
    double m_sinBeta = 0;
    double m_grooveLength = 0, m_grooveArea = 0;
    double m_periodLength = 0, m_periodArea = 0, m_totalLength = 0, m_totalArea = 0;
    double m_invRadius = 0, m_invHalfRadius2 = 0, m_invArcRadius = 0, m_invPeriodLength = 0, m_invPeriodArea = 0;
    double m_tablePerArea = 0;
    SinCosTable m_sinCos;
    std::vector<double> m_rotation;   ///< cos, sin of each flute centre (even) and fillet centre (odd)
    std::vector<double> m_psiAtArea;  ///< ψ at swept areas m/kAreaTable of a flute's
};

class SyntheticStreamReader final : public io::PointReader {
public:
    SyntheticStreamReader(const SyntheticStreamOptions& o, DrumSampler sampler)
        : io::PointReader("synthetic-drum", (o.points - o.offset) * kBytesPerPoint), m_o(o),
          m_sampler(std::move(sampler)), m_next(o.offset)
    {
        m_header.format = "synthetic-drum";
        m_header.declaredPoints = o.points - o.offset;
        m_header.schema.hasNormals = true;
        const SyntheticDrumAreas areas = m_sampler.areas();
        m_total = areas.lateral + 2.0 * areas.bed;
        m_bedShare = areas.bed / m_total;
        m_lateralShare = areas.lateral / m_total;
        // Ordered: bottom face, lateral surface, top face, counts in proportion to their areas.
        const double n = static_cast<double>(o.points);
        const std::uint64_t bottom = std::min<std::uint64_t>(o.points, static_cast<std::uint64_t>(std::llround(n * m_bedShare)));
        const std::uint64_t lateral = std::min<std::uint64_t>(
            o.points - bottom, static_cast<std::uint64_t>(std::llround(n * m_lateralShare)));
        const std::uint64_t top = o.points - bottom - lateral;
        m_segments[0] = segment(Surface::Bottom, 0, bottom, static_cast<double>(bottom) / (2.0 * kTwoPi));
        m_segments[1] = segment(Surface::Lateral, bottom, lateral, static_cast<double>(lateral) * o.height / areas.perimeter);
        m_segments[2] = segment(Surface::Top, bottom + lateral, top, static_cast<double>(top) / (2.0 * kTwoPi));
    }

    Result<std::size_t> read(io::PointBatch& batch, std::size_t maxPoints) override
    {
        const std::size_t n = static_cast<std::size_t>(std::min<std::uint64_t>(maxPoints, m_o.points - m_next));
        // Not batch.reset(): resizing to the size of the previous batch writes nothing.
        batch.colors.clear();
        batch.scalars.clear();
        batch.positions.resize(3 * n);
        batch.normals.resize(3 * n);
        double* p = batch.positions.data();
        float* nrm = batch.normals.data();
        if (m_o.shuffled) {
            // Sorted into lateral and bed points per block (without branches), then each kind in its
            // own loop: an unpredictable branch per point would serialise the work.
            constexpr std::size_t kBlock = 512;
            std::array<std::uint32_t, kBlock> lateral, bed;
            for (std::size_t b0 = 0; b0 < n; b0 += kBlock) {
                const std::size_t b1 = std::min(n, b0 + kBlock);
                std::size_t nl = 0, nb = 0;
                for (std::size_t j = b0; j < b1; ++j) {
                    const double pick = unit(bits(m_next + j, 0));
                    const bool isBed = pick < m_bedShare || pick >= m_bedShare + m_lateralShare;
                    lateral[nl] = static_cast<std::uint32_t>(j);
                    bed[nb] = static_cast<std::uint32_t>(j) | (pick >= m_bedShare ? 0x80000000u : 0u);
                    nl += !isBed;
                    nb += isBed;
                }
                for (std::size_t q = 0; q < nl; ++q) {
                    const std::size_t j = lateral[q];
                    const std::uint64_t b = bits(m_next + j, 1);
                    m_sampler.lateral(unitHigh(b), unitLow(b), p + 3 * j, nrm + 3 * j);
                }
                for (std::size_t q = 0; q < nb; ++q) {
                    const std::size_t j = bed[q] & 0x7FFFFFFFu;
                    const std::uint64_t b = bits(m_next + j, 1);
                    m_sampler.bed(unitHigh(b), unitLow(b), (bed[q] >> 31) != 0, p + 3 * j, nrm + 3 * j);
                }
            }
        } else {
            for (const Segment& seg : m_segments) {
                const std::uint64_t begin = std::max(m_next, seg.first), end = std::min(m_next + n, seg.first + seg.count);
                if (begin >= end) continue;
                std::uint64_t k = begin - seg.first, row = k % seg.rows;
                for (std::uint64_t i = begin; i < end; ++i, ++k) {
                    const std::uint64_t b = bits(i, 1);
                    const double along = (static_cast<double>(k) + unitHigh(b)) * seg.invCount;
                    const double across = (static_cast<double>(row) + unitLow(b)) * seg.invRows;
                    point(seg.surface, along, across, p + 3 * (i - m_next), nrm + 3 * (i - m_next));
                    if (++row == seg.rows) row = 0;
                }
            }
        }
        if (m_o.noise > 0)
            for (std::size_t j = 0; j < n; ++j) addNoise(m_next + j, p + 3 * j, nrm + 3 * j);
        m_next += n;
        m_pointsRead += n;
        return n;
    }

    std::uint64_t bytesConsumed() const override { return m_pointsRead * kBytesPerPoint; }

private:
    enum class Surface { Bottom, Lateral, Top };

    /** Ordered mode: a run of consecutive points on one surface, in columns of `rows` points. */
    struct Segment {
        Surface surface = Surface::Bottom;
        std::uint64_t first = 0, count = 0, rows = 1;
        double invCount = 0, invRows = 1;
    };

    /** A segment whose columns have about √squareRows rows (cells about square). */
    static Segment segment(Surface surface, std::uint64_t first, std::uint64_t count, double squareRows)
    {
        Segment s{surface, first, count, 1, count > 0 ? 1.0 / static_cast<double>(count) : 0.0, 1.0};
        s.rows = std::max<std::uint64_t>(1, static_cast<std::uint64_t>(std::llround(std::sqrt(squareRows))));
        s.invRows = 1.0 / static_cast<double>(s.rows);
        return s;
    }

    void point(Surface surface, double along, double across, double* p, float* n) const
    {
        if (surface == Surface::Lateral) m_sampler.lateral(along, across, p, n);
        else m_sampler.bed(along, across, surface == Surface::Top, p, n);
    }

    /** Variate k (0..2) of point i: output 3i + k of SplitMix64 seeded with the seed. */
    std::uint64_t bits(std::uint64_t i, std::uint64_t k) const { return mix(m_o.seed + (3 * i + k + 1) * kGolden); }

    /** Moves the point along its normal by a Gaussian variate of σ = noise (Box–Muller). */
    void addNoise(std::uint64_t i, double* p, const float* n) const
    {
        const std::uint64_t b = bits(i, 2);
        const double u1 = (static_cast<double>(b >> 32) + 0.5) * 0x1.0p-32; // (0, 1)
        const double u2 = static_cast<double>(b & 0xFFFFFFFFull) * 0x1.0p-32;
        const double g = m_o.noise * std::sqrt(-2.0 * std::log(u1)) * std::cos(kTwoPi * u2);
        for (int c = 0; c < 3; ++c) p[c] += g * static_cast<double>(n[c]);
    }

    SyntheticStreamOptions m_o;
    DrumSampler m_sampler;
    std::uint64_t m_next;
    double m_total = 0, m_bedShare = 0, m_lateralShare = 0;
    std::array<Segment, 3> m_segments{};
};

} // namespace

Result<SyntheticDrumAreas> syntheticDrumAreas(const SyntheticStreamOptions& options)
{
    auto sampler = DrumSampler::make(options);
    if (!sampler) return sampler.error();
    return sampler->areas();
}

Result<std::unique_ptr<io::PointReader>> openSyntheticStream(const SyntheticStreamOptions& options)
{
    if (options.points == 0) return invalid("the stream needs at least one point");
    if (options.offset > options.points)
        return invalid("offset " + std::to_string(options.offset) + " is past the end (" +
                       std::to_string(options.points) + " points)");
    auto sampler = DrumSampler::make(options);
    if (!sampler) return sampler.error();
    return std::unique_ptr<io::PointReader>(std::make_unique<SyntheticStreamReader>(options, std::move(*sampler)));
}

} // namespace stylos::core::synth
