#include "FitRadialKernel.h"

#include "FitAzimuthProfile.h"

#include <algorithm>
#include <cmath>
#include <limits>

#if defined(__SSE2__)
#include <emmintrin.h>
#endif

namespace stylos::core::unroll::detail {

namespace {

// Two points at a time in the compiler's vector types (GCC and Clang): SSE2 on x86-64, NEON on ARM,
// plain scalar code elsewhere; comparisons give lane masks and `mask ? a : b` selects without branches.
typedef double Pair __attribute__((vector_size(16)));

Pair splat(double x)
{
    return Pair{x, x};
}

Pair sqrtOf(Pair x)
{
#if defined(__SSE2__)
    return Pair(_mm_sqrt_pd(__m128d(x)));
#else
    return Pair{std::sqrt(x[0]), std::sqrt(x[1])};
#endif
}

Pair absOf(Pair x)
{
    return x < 0.0 ? -x : x;
}
Pair minOf(Pair a, Pair b)
{
    return a < b ? a : b;
}
Pair maxOf(Pair a, Pair b)
{
    return a > b ? a : b;
}

/** FitAzimuthProfile::fastAngle() on two lanes. */
Pair fastAngles(Pair x, Pair y)
{
    constexpr double pi = 3.14159265358979323846;
    const Pair ax = absOf(x), ay = absOf(y);
    const Pair z = minOf(ax, ay) / maxOf(maxOf(ax, ay), splat(1e-300));
    Pair a = z * (0.25 * pi + 0.273 * (1.0 - z));
    a = ay > ax ? 0.5 * pi - a : a;
    a = x < 0.0 ? pi - a : a;
    a = y < 0.0 ? 2.0 * pi - a : a;
    return a < 2.0 * pi ? a : splat(0.0);
}

template <bool kEquations, bool kHistogram, bool kCollect, bool kProfiled, bool kCone>
void accumulate(const float* xyz, std::size_t begin, std::size_t end, const RadialKernel& k, double tau,
                FitResidualHistogram* histogram, RadialSamples* samples, RadialSums& out)
{
    constexpr int kParameters = kCone ? 6 : 5;
    Pair jtj[21] = {}, jtr[6] = {};
    Pair cost = {}, sumSquares = {}, sumTrueSquares = {}, sumT = {}, count = {};
    Pair minT = splat(std::numeric_limits<double>::infinity()), maxT = -minT;
    const double tau2 = tau * tau;
    const double slope = kCone ? k.slope : 0.0;
    const std::size_t pairs = (end - begin) / 2;
    for (std::size_t pair = 0; pair < pairs; ++pair) {
        const float* p = xyz + 3 * (begin + 2 * pair);
        const Pair wx = Pair{p[0], p[3]} - k.qx, wy = Pair{p[1], p[4]} - k.qy, wz = Pair{p[2], p[5]} - k.qz;
        const Pair t = wx * k.dx + wy * k.dy + wz * k.dz;
        const Pair we1 = wx * k.e1x + wy * k.e1y + wz * k.e1z;
        const Pair we2 = wx * k.e2x + wy * k.e2y + wz * k.e2z;
        const Pair rho = sqrtOf(we1 * we1 + we2 * we2); // w − t·d expressed in (e1, e2)
        const Pair bare = rho - (k.radius + slope * t);
        Pair angle = {}, f = {};
        if constexpr (kProfiled || kCollect) angle = fastAngles(we1, we2);
        if constexpr (kProfiled)
            for (int l = 0; l < 2; ++l)
                f[l] = FitAzimuthProfile::interpolate(k.profileValues, k.profileSlopes, k.profileBins,
                                                      k.profilePerRadian, angle[l]);
        const Pair h = bare - f;
        const Pair size = absOf(h);
        if constexpr (kHistogram) {
            histogram->add(size[0]);
            histogram->add(size[1]);
        }
        // An outlier's values become 0 (selections, not branches; a NaN point stays out of the sums).
        const auto inlier = size <= tau;
        const Pair in = inlier ? splat(1.0) : splat(0.0);
        const Pair hm = inlier ? h : 0.0, bm = inlier ? bare : 0.0, tm = inlier ? t : 0.0;
        cost += hm * hm + (1.0 - in) * tau2;
        sumSquares += hm * hm;
        sumTrueSquares += bm * bm;
        sumT += tm;
        count += in;
        minT = minOf(minT, inlier ? t : minT);
        maxT = maxOf(maxT, inlier ? t : maxT);
        if constexpr (kCollect)
            for (int l = 0; l < 2; ++l)
                if (inlier[l]) samples->emplace_back(std::uint32_t(angle[l] * 0x1p28), float(bare[l]));
        if constexpr (kEquations) {
            const Pair e1m = inlier ? we1 : 0.0, e2m = inlier ? we2 : 0.0;
            const Pair inverse = 1.0 / (inlier ? rho : 1.0);
            const Pair a = e1m * inverse, b = e2m * inverse;
            Pair j[6] = {-(tm * a), -(tm * b), -a, -b, -in, -tm};
            if constexpr (kCone) {
                j[0] -= slope * e1m;
                j[1] -= slope * e2m;
            }
            int index = 0;
            for (int r = 0; r < kParameters; ++r) {
                for (int c = 0; c <= r; ++c)
                    jtj[index++] += j[r] * j[c];
                jtr[r] += j[r] * hm;
            }
        }
    }
    // The lanes, then an odd last point (a pair whose second lane repeats it and is dropped would
    // cost the same; this keeps one code path).
    for (int i = 0; i < 21; ++i)
        out.jtj[std::size_t(i)] = jtj[i][0] + jtj[i][1];
    for (int i = 0; i < 6; ++i)
        out.jtr[std::size_t(i)] = jtr[i][0] + jtr[i][1];
    out.cost = cost[0] + cost[1];
    out.sumSquares = sumSquares[0] + sumSquares[1];
    out.sumTrueSquares = sumTrueSquares[0] + sumTrueSquares[1];
    out.sumT = sumT[0] + sumT[1];
    out.minT = std::min(minT[0], minT[1]);
    out.maxT = std::max(maxT[0], maxT[1]);
    out.inliers = std::uint64_t(count[0] + count[1]);
    out.points = 2 * pairs;
    if ((end - begin) % 2 == 1) {
        // The last point twice in a pair, the sums of one lane kept.
        const std::size_t last = end - 1;
        float twice[6] = {xyz[3 * last], xyz[3 * last + 1], xyz[3 * last + 2],
                          xyz[3 * last], xyz[3 * last + 1], xyz[3 * last + 2]};
        RadialSums both;
        RadialSamples extra;
        FitResidualHistogram* none = nullptr;
        accumulate<kEquations, false, kCollect, kProfiled, kCone>(twice, 0, 2, k, tau, none, &extra, both);
        RadialSums one;
        for (int i = 0; i < 21; ++i)
            one.jtj[std::size_t(i)] = 0.5 * both.jtj[std::size_t(i)];
        for (int i = 0; i < 6; ++i)
            one.jtr[std::size_t(i)] = 0.5 * both.jtr[std::size_t(i)];
        one.cost = 0.5 * both.cost;
        one.sumSquares = 0.5 * both.sumSquares;
        one.sumTrueSquares = 0.5 * both.sumTrueSquares;
        one.sumT = 0.5 * both.sumT;
        one.minT = both.minT;
        one.maxT = both.maxT;
        one.inliers = both.inliers / 2;
        one.points = 1;
        out.add(one);
        if constexpr (kHistogram) {
            const float* q = xyz + 3 * last;
            const double wx = q[0] - k.qx, wy = q[1] - k.qy, wz = q[2] - k.qz;
            const double t = wx * k.dx + wy * k.dy + wz * k.dz;
            const double we1 = wx * k.e1x + wy * k.e1y + wz * k.e1z, we2 = wx * k.e2x + wy * k.e2y + wz * k.e2z;
            double h = std::sqrt(we1 * we1 + we2 * we2) - (k.radius + slope * t);
            if constexpr (kProfiled)
                h -= FitAzimuthProfile::interpolate(k.profileValues, k.profileSlopes, k.profileBins, k.profilePerRadian,
                                                    FitAzimuthProfile::fastAngle(we1, we2));
            histogram->add(std::abs(h));
        }
        if constexpr (kCollect)
            if (!extra.empty()) samples->push_back(extra.front());
    }
}

template <std::size_t... I>
constexpr std::array<RadialAccumulate, sizeof...(I)> accumulateTable(std::index_sequence<I...>)
{
    return {&accumulate<(I & 1) != 0, (I & 2) != 0, (I & 4) != 0, (I & 8) != 0, (I & 16) != 0>...};
}

} // namespace

void RadialSums::add(const RadialSums& other)
{
    for (std::size_t i = 0; i < 21; ++i)
        jtj[i] += other.jtj[i];
    for (std::size_t i = 0; i < 6; ++i)
        jtr[i] += other.jtr[i];
    cost += other.cost;
    sumSquares += other.sumSquares;
    sumTrueSquares += other.sumTrueSquares;
    sumT += other.sumT;
    minT = std::min(minT, other.minT);
    maxT = std::max(maxT, other.maxT);
    inliers += other.inliers;
    points += other.points;
}

RadialAccumulate radialAccumulate(bool equations, bool histogram, bool collect, bool profiled, bool cone)
{
    static constexpr auto table = accumulateTable(std::make_index_sequence<32>{});
    return table[std::size_t(equations) | std::size_t(histogram) << 1 | std::size_t(collect) << 2 |
                 std::size_t(profiled) << 3 | std::size_t(cone) << 4];
}

} // namespace stylos::core::unroll::detail
