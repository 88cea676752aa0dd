// fitSurface: cylinder, cone and revolution against generated truth (axis, radius, slope, meridian), the
// given-axis path, refusals of clouds that are no surface of revolution, cancel, progress, determinism
// and the real Buddha scan.
#include "FitTestSupport.h"

#include "stylos/core/synth/DrumShape.h"
#include "stylos/core/synth/OmphalosShape.h"
#include "stylos/core/unroll/SurfaceFit.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <vector>

namespace stylos::core::unroll {
namespace {

using synth::SyntheticKind;
using test::angleDegrees;
using test::axisDistance;
using test::trueAxis;

constexpr double kDegreeTolerance = 0.02; // the targets
constexpr double kMetreTolerance = 0.0001;

/** A plain drum (no flutes) seen all round by one station: the axis of its points is exactly known. */
const test::FitScan& plainDrum()
{
    return test::generatedScan("plain", SyntheticKind::Drum, test::allRound(0.006, 5, 0));
}
const test::FitScan& flutedDrum()
{
    return test::generatedScan("fluted", SyntheticKind::Drum, test::allRound(0.006, 5, 48));
}
const test::FitScan& omphalos()
{
    auto o = test::allRound(0.006, 9, 48);
    return test::generatedScan("omphalos", SyntheticKind::Omphalos, o);
}

FitReport fitOk(const cloud::PointCloud& cloud, const FitOptions& options)
{
    auto report = fitSurface(cloud, options);
    EXPECT_TRUE(report.ok()) << (report.ok() ? "" : report.error().message);
    return report.ok() ? *report : FitReport{};
}

FitOptions kindOptions(SurfaceKind kind, unsigned threads = 0)
{
    FitOptions options;
    options.kind = kind;
    options.threads = threads;
    return options;
}

TEST(SurfaceFitTest, PlainDrumAxisAndRadiusMatchTheTruth)
{
    const auto& scan = plainDrum();
    const FitReport report = fitOk(scan.cloud, kindOptions(SurfaceKind::Cylinder));
    const Surface& s = report.surface;
    const Axis truth = trueAxis(scan.truth, 0);
    EXPECT_EQ(s.kind(), SurfaceKind::Cylinder);
    EXPECT_LT(angleDegrees(s.axis().direction, truth.direction), kDegreeTolerance);
    EXPECT_LT(axisDistance(s.axis(), truth, 0.5), kMetreTolerance);
    EXPECT_NEAR(s.radius(), 0.55, kMetreTolerance);
    EXPECT_EQ(s.referenceRadius(), s.radius());
    // The axis point is at the lowest inlier: one of the beds, whichever way the axis points (its
    // largest world component is positive).
    const double t = (s.axis().point - truth.point).dot(truth.direction);
    EXPECT_LT(std::min(std::abs(t), std::abs(t - 0.5)), 0.003) << t;
    const Eigen::Vector3d d = s.axis().direction;
    Eigen::Index largest;
    d.cwiseAbs().maxCoeff(&largest);
    EXPECT_GT(d[largest], 0.0);
    // The bed faces (about half of the points) are trimmed; the rest fits to the noise.
    EXPECT_EQ(report.points, scan.cloud.size());
    EXPECT_GT(report.inlierFraction, 0.35);
    EXPECT_LT(report.inlierFraction, 0.6);
    EXPECT_LT(report.rmsResidual, 0.0004);
    EXPECT_GT(report.iterations, 1);
    EXPECT_GT(report.seconds, 0.0);
}

TEST(SurfaceFitTest, FlutedDrumRadiusIsTheMeanOfTheFlutedOutline)
{
    // The scan samples the lateral surface uniformly in azimuth; the least-squares radius (with the
    // flute profile taken out, whose mean is zero) is the mean of the outline's radius over azimuth.
    synth::DrumParameters p;
    p.grooves = 48;
    const synth::DrumShape shape(p);
    double sum = 0.0;
    constexpr int kSteps = 200000;
    for (int i = 0; i < kSteps; ++i)
        sum += shape.fluteRadius(2.0 * std::numbers::pi * (i + 0.5) / kSteps);
    const double meanOutline = sum / kSteps;
    ASSERT_LT(meanOutline, 0.55 - 0.004); // flutes 8 mm deep: far from the fillet radius

    const auto& scan = flutedDrum();
    const FitReport report = fitOk(scan.cloud, kindOptions(SurfaceKind::Cylinder));
    const Axis truth = trueAxis(scan.truth, 0);
    EXPECT_LT(angleDegrees(report.surface.axis().direction, truth.direction), kDegreeTolerance);
    EXPECT_LT(axisDistance(report.surface.axis(), truth, 0.5), kMetreTolerance);
    EXPECT_NEAR(report.surface.radius(), meanOutline, kMetreTolerance);
    // The residual is the flutes' (a few mm), not the noise: RMS reports r − R.
    EXPECT_GT(report.rmsResidual, 0.002);
}

TEST(SurfaceFitTest, ScansWithRegistrationErrorsFitWithinThatError)
{
    // Three overlapping scans, each registered with its own error (≤ 0.05°, ≤ 0.3 mm): the points have
    // no single true axis; the fit must lie within the scans' spread of the nominal one.
    const auto& scan = test::generatedScan("drum3", SyntheticKind::Drum, test::coarse(0.006, 7));
    const FitReport report = fitOk(scan.cloud, kindOptions(SurfaceKind::Cylinder));
    const Axis nominal = trueAxis(scan.truth);
    EXPECT_LT(angleDegrees(report.surface.axis().direction, nominal.direction), 0.05);
    EXPECT_LT(axisDistance(report.surface.axis(), nominal, 0.5), scan.truth["registrationBound"].get<double>());
}

TEST(SurfaceFitTest, ConeAxisSlopeAndMeanRadius)
{
    const test::ConeCloud cone = test::coneCloud(0.5, 0.4, 0.6, 150000, 0.0003, 0.05, 21);
    const FitReport report = fitOk(cone.cloud, kindOptions(SurfaceKind::Cone));
    const Surface& s = report.surface;
    EXPECT_EQ(s.kind(), SurfaceKind::Cone);
    EXPECT_LT(angleDegrees(s.axis().direction, cone.axis.direction), kDegreeTolerance);
    EXPECT_LT(axisDistance(s.axis(), cone.axis, 0.6), kMetreTolerance);
    // The wider end at the bottom: the axis points to the narrow end, its point on the wide bed.
    EXPECT_GT(s.axis().direction.dot(cone.axis.direction), 0.0);
    EXPECT_NEAR((s.axis().point - cone.axis.point).dot(cone.axis.direction), 0.0, 0.002);
    EXPECT_NEAR(s.slope(), -0.1 / 0.6, 1e-4);
    EXPECT_NEAR(s.radius() + s.slope() * (cone.axis.point - s.axis().point).dot(s.axis().direction), 0.5,
                kMetreTolerance);
    EXPECT_NEAR(s.referenceRadius(), cone.meanLateralRadius, 2 * kMetreTolerance);
}

/** RMS and largest |h| of the true omphalos meridian (bare ovoid, plinth) against the fitted surface. */
std::pair<double, double> meridianDeviation(const Surface& s, const Eigen::Affine3d& pose)
{
    const synth::OmphalosShape shape(synth::OmphalosParameters{});
    double sum = 0.0, worst = 0.0;
    int n = 0;
    for (double arc = 0.0; arc <= shape.meridianLength(); arc += 0.005) {
        const auto m = shape.meridian(arc);
        const Eigen::Vector3d p = pose * Eigen::Vector3d(m.r, 0.0, m.z);
        const Eigen::Vector3d w = p - s.axis().point;
        const double t = w.dot(s.axis().direction);
        const auto c = s.meridianCoords(t, (w - t * s.axis().direction).norm());
        EXPECT_TRUE(c.has_value()) << "arc " << arc;
        if (!c) continue;
        sum += c->h * c->h;
        worst = std::max(worst, std::abs(c->h));
        ++n;
    }
    return {std::sqrt(sum / n), worst};
}

TEST(SurfaceFitTest, OmphalosRevolutionFollowsTheTrueMeridian)
{
    const auto& scan = omphalos();
    const FitReport report = fitOk(scan.cloud, kindOptions(SurfaceKind::Revolution));
    const Surface& s = report.surface;
    ASSERT_EQ(s.kind(), SurfaceKind::Revolution);
    ASSERT_NE(s.meridian(), nullptr);
    const Axis truth = trueAxis(scan.truth, 0);
    EXPECT_LT(angleDegrees(s.axis().direction, truth.direction), 0.01);
    EXPECT_LT(axisDistance(s.axis(), truth, 1.2), kMetreTolerance);
    // Bottom to top: from the plinth's lower edge (r = 0.5 at t = 0) to the apex.
    EXPECT_GT(s.axis().direction.dot(truth.direction), 0.0);
    const auto& v = s.meridian()->vertices();
    EXPECT_NEAR(v.front().x(), 0.0, 1e-12);
    EXPECT_NEAR(v.front().y(), 0.5, 0.002);
    EXPECT_LT(v.back().y(), 0.03);
    EXPECT_NEAR(v.back().x(), 1.2, 0.003);
    // Close to the true meridian: sub-millimetre on the whole, a few millimetres where it rounds the
    // plinth's corners and follows the rings that edge the net (relief the true bare meridian lacks).
    const auto [rms, worst] = meridianDeviation(s, test::affineOf(scan.truth["stations"][0]["toOutput"]));
    EXPECT_LT(rms, 0.001);
    EXPECT_LT(worst, 0.008);
    // The reference radius is the arc-length-weighted mean radius of the meridian.
    double sum = 0.0, length = 0.0;
    for (std::size_t i = 1; i < v.size(); ++i) {
        const double l = (v[i] - v[i - 1]).norm();
        sum += l * 0.5 * (v[i].y() + v[i - 1].y());
        length += l;
    }
    EXPECT_NEAR(s.referenceRadius(), sum / length, 1e-12);
    EXPECT_GT(s.meridian()->reach(), 0.01);
}

TEST(SurfaceFitTest, GivenAxisFitsOnlyTheRadius)
{
    const auto& scan = plainDrum();
    FitOptions options = kindOptions(SurfaceKind::Cylinder);
    Axis given = trueAxis(scan.truth, 0);
    given.point += 0.3 * given.direction; // anywhere on the line
    given.direction = -given.direction;   // and either way: the user's direction is kept
    options.axis = given;
    const FitReport report = fitOk(scan.cloud, options);
    const Surface& s = report.surface;
    EXPECT_EQ(s.axis().direction, given.direction);
    EXPECT_LT(test::distanceToLine(s.axis().point, given), 1e-9);
    EXPECT_NEAR(s.radius(), 0.55, kMetreTolerance);
    // The point slides along the line to the lowest inlier: along the reversed axis, the upper bed
    // (0.5 m up the drum, 0.2 m below the given point).
    EXPECT_NEAR((s.axis().point - given.point).dot(given.direction), -0.2, 0.003);
}

TEST(SurfaceFitTest, GivenAxisFitsOnlyTheSlopeOfACone)
{
    const test::ConeCloud cone = test::coneCloud(0.3, 0.36, 0.4, 60000, 0.0002, 0.0, 4);
    FitOptions options = kindOptions(SurfaceKind::Cone);
    options.axis = cone.axis;
    const FitReport report = fitOk(cone.cloud, options);
    EXPECT_EQ(report.surface.axis().direction, cone.axis.direction);
    EXPECT_NEAR(report.surface.slope(), 0.06 / 0.4, 1e-4);
    EXPECT_NEAR((report.surface.axis().point - cone.axis.point).dot(cone.axis.direction), 0.0, 0.002);
    EXPECT_NEAR(report.surface.radius(), 0.3, kMetreTolerance);
}

TEST(SurfaceFitTest, GivenAxisFitsOnlyTheMeridian)
{
    const auto& scan = omphalos();
    FitOptions options = kindOptions(SurfaceKind::Revolution);
    options.axis = trueAxis(scan.truth, 0);
    const FitReport report = fitOk(scan.cloud, options);
    EXPECT_EQ(report.surface.axis().direction, options.axis->direction);
    EXPECT_LT(test::distanceToLine(report.surface.axis().point, *options.axis), 1e-9);
    const auto [rms, worst] = meridianDeviation(report.surface, test::affineOf(scan.truth["stations"][0]["toOutput"]));
    EXPECT_LT(rms, 0.001);
    EXPECT_LT(worst, 0.008);
}

TEST(SurfaceFitTest, GivenAxisFitsAFragmentsOuterFace)
{
    // A piece of a fluted drum: its outer face (50° × 0.27 m) is about a quarter of its points, among
    // rough fracture faces and a bed face. About the drum's axis, the radius is the outer face's.
    const auto& scan = test::generatedScan("fragment", SyntheticKind::Fragment, test::coarse(0.005, 3));
    FitOptions options = kindOptions(SurfaceKind::Cylinder);
    options.axis = trueAxis(scan.truth);
    const FitReport report = fitOk(scan.cloud, options);
    EXPECT_NEAR(report.surface.radius(), 0.545, 0.001); // the flutes' mean over the arc, below the fillets
    EXPECT_GT(report.inlierFraction, 0.2);
    EXPECT_LT(report.inlierFraction, 0.4);
    EXPECT_LT(report.rmsResidual, 0.004);
}

TEST(SurfaceFitTest, FindsAFragmentsOwnAxisWithoutHelp)
{
    // The outer face is a minority of the fragment's normals: the line complex alone leans towards the
    // fracture planes (an axis 30° off was accepted); the seed from pairs of normals finds the drum's.
    for (std::uint64_t seed : {3u, 5u, 8u}) {
        const auto& scan = test::generatedScan("fragment-own-" + std::to_string(seed), SyntheticKind::Fragment,
                                               test::coarse(0.004, seed));
        const FitReport report = fitOk(scan.cloud, kindOptions(SurfaceKind::Cylinder));
        const Axis truth = trueAxis(scan.truth);
        const double angle = std::acos(std::min(1.0, std::abs(report.surface.axis().direction.dot(truth.direction))));
        EXPECT_LT(angle * 180.0 / std::numbers::pi, 0.1) << "seed " << seed;
        // An arc of 50° leaves the radius and the radial position of the axis weakly determined together
        // (measured: 0.525–0.538 m and 7–20 mm off for these seeds); docking fixes them against the drum.
        EXPECT_LT(test::distanceToLine(report.surface.axis().point, truth), 0.03) << "seed " << seed;
        EXPECT_NEAR(report.surface.radius(), 0.545, 0.03) << "seed " << seed;
    }
}

TEST(SurfaceFitTest, RefusesTooFewPoints)
{
    const test::ConeCloud cone = test::coneCloud(0.5, 0.5, 0.5, 99, 0.0, 0.0, 3);
    for (SurfaceKind kind : {SurfaceKind::Cylinder, SurfaceKind::Cone, SurfaceKind::Revolution}) {
        auto report = fitSurface(cone.cloud, kindOptions(kind));
        ASSERT_FALSE(report.ok());
        EXPECT_EQ(report.error().code, ErrorCode::InvalidArgument);
        EXPECT_EQ(report.error().message, "cone: 99 points: too few to fit a surface (at least 100)");
    }
}

TEST(SurfaceFitTest, RefusesABadGivenAxis)
{
    const test::ConeCloud cone = test::coneCloud(0.5, 0.4, 0.5, 1000, 0.0, 0.0, 3);
    FitOptions options;
    options.axis = Axis{Eigen::Vector3d::Zero(), Eigen::Vector3d::Zero()};
    auto report = fitSurface(cone.cloud, options);
    ASSERT_FALSE(report.ok());
    EXPECT_EQ(report.error().code, ErrorCode::InvalidArgument);
    options.axis = Axis{Eigen::Vector3d(std::nan(""), 0, 0), Eigen::Vector3d::UnitZ()};
    report = fitSurface(cone.cloud, options);
    ASSERT_FALSE(report.ok());
    EXPECT_EQ(report.error().code, ErrorCode::InvalidArgument);
}

TEST(SurfaceFitTest, RefusesCloudsThatAreNoSurfaceOfRevolution)
{
    struct Case {
        test::BadShape shape;
        SurfaceKind kind;
        const char* expected;
    };
    const Case cases[] = {
        {test::BadShape::Plane, SurfaceKind::Cylinder, "plane: not a cylinder: RMS residual "},
        {test::BadShape::Box, SurfaceKind::Cylinder, "box: not a cylinder: RMS residual "},
        {test::BadShape::Blobs, SurfaceKind::Cylinder, "blobs: not a cylinder: RMS residual "},
        {test::BadShape::Plane, SurfaceKind::Cone, "plane: not a cone: "},
        {test::BadShape::Box, SurfaceKind::Cone, "box: not a cone: RMS residual "},
        {test::BadShape::Blobs, SurfaceKind::Cone, "blobs: not a cone: RMS residual "},
        {test::BadShape::Plane, SurfaceKind::Revolution,
         "plane: not a surface of revolution: the points lie in a plane"},
        {test::BadShape::Box, SurfaceKind::Revolution, "box: not a surface of revolution: RMS residual "},
        {test::BadShape::Blobs, SurfaceKind::Revolution, "blobs: not a surface of revolution: RMS residual "},
    };
    for (const Case& c : cases) {
        const cloud::PointCloud cloud = test::badCloud(c.shape, 20000, 8);
        auto report = fitSurface(cloud, kindOptions(c.kind));
        ASSERT_FALSE(report.ok()) << c.expected << report->surface.toJson().dump() << " rms " << report->rmsResidual
                                  << " inliers " << report->inlierFraction;
        EXPECT_EQ(report.error().code, ErrorCode::InvalidArgument);
        EXPECT_EQ(report.error().message.rfind(c.expected, 0), 0u) << report.error().message;
    }
}

TEST(SurfaceFitTest, RefusesANearlyFlatCloudUnlessTheAxisIsGiven)
{
    // 20 000 points of a 1 m × 1 m patch of a cylinder of radius 50 m (an arc of 1.1°), 1 mm noise: any
    // huge cylinder fits it, as one fits an airborne terrain scan.
    synth::Random random(4);
    cloud::PointCloud cloud;
    cloud.source = "terrain";
    const double radius = 50.0;
    for (int i = 0; i < 20000; ++i) {
        const double phi = random.uniform(-0.5, 0.5) / radius, z = random.uniform(0.0, 1.0);
        const double r = radius + 0.001 * random.normal();
        cloud.addWorld({r * std::cos(phi), r * std::sin(phi), z});
    }
    const auto free = fitSurface(cloud, kindOptions(SurfaceKind::Cylinder));
    ASSERT_FALSE(free.ok()) << free->surface.toJson().dump();
    EXPECT_EQ(free.error().message.rfind("terrain: not a cylinder: ", 0), 0u) << free.error().message;

    FitOptions given = kindOptions(SurfaceKind::Cylinder);
    given.axis = Axis{{0.0, 0.0, 0.0}, {0.0, 0.0, 1.0}};
    const auto fitted = fitSurface(cloud, given);
    ASSERT_TRUE(fitted.ok()) << fitted.error().message;
    EXPECT_NEAR(fitted->surface.radius(), radius, 1e-3);
}

TEST(SurfaceFitTest, RefusesAnAirborneTerrainScanAsNearlyFlat)
{
    // Autzen (airborne LiDAR, 339 m RMS size): a cylinder of radius ~9.6 km and a cone of ~1.7 km fit it.
    SKIP_WITHOUT_SHARED_DATA();
    auto loaded = cloud::loadPointCloud(test::sharedData() / "formats" / "autzen_trim.las");
    ASSERT_TRUE(loaded.ok()) << loaded.error().message;
    for (SurfaceKind kind : {SurfaceKind::Cylinder, SurfaceKind::Cone}) {
        const auto fitted = fitSurface(*loaded, kindOptions(kind));
        ASSERT_FALSE(fitted.ok()) << fitted->surface.toJson().dump();
        EXPECT_NE(fitted.error().message.find("autzen_trim.las: not a c"), std::string::npos) << fitted.error().message;
        EXPECT_NE(fitted.error().message.find("the points are nearly flat"), std::string::npos)
            << fitted.error().message;
    }
}

TEST(SurfaceFitTest, RefusesSeparateObjectsAlongTheAxis)
{
    // Two drums one above the other with a gap as tall as both: each piece is a cylinder, the pair
    // is not one surface to unroll.
    const test::ConeCloud a = test::coneCloud(0.3, 0.3, 0.3, 20000, 0.0002, 0.0, 5);
    cloud::PointCloud cloud = a.cloud;
    cloud.source = "pair";
    for (std::size_t i = 0; i < a.cloud.size(); ++i)
        cloud.addWorld(a.cloud.world(i) + 0.9 * a.axis.direction);
    auto report = fitSurface(cloud, kindOptions(SurfaceKind::Cylinder));
    ASSERT_FALSE(report.ok());
    EXPECT_EQ(report.error().code, ErrorCode::InvalidArgument);
    EXPECT_EQ(report.error().message.rfind("pair: not a cylinder: the points form separate groups along the axis", 0),
              0u)
        << report.error().message;
}

/** Cancels once the fit has reported @p at of its progress. */
class CancelAt final : public ProgressSink {
  public:
    explicit CancelAt(double at) : m_at(at) {}
    void update(double fraction) override
    {
        if (fraction < m_last) m_monotone = false;
        m_last = fraction;
        if (fraction >= m_at) m_cancel = true;
    }
    bool isCancelRequested() const override { return m_cancel; }
    double last() const { return m_last; }
    bool monotone() const { return m_monotone; }

  private:
    double m_at;
    std::atomic<bool> m_cancel{false};
    double m_last = 0.0;
    bool m_monotone = true;
};

TEST(SurfaceFitTest, CancelStopsTheFit)
{
    const auto& scan = plainDrum();
    for (SurfaceKind kind : {SurfaceKind::Cylinder, SurfaceKind::Revolution}) {
        for (double at : {0.0, 0.5}) {
            CancelAt sink(at);
            if (at == 0.0) sink.update(0.0); // cancelled before it starts
            auto report = fitSurface(scan.cloud, kindOptions(kind), &sink);
            ASSERT_FALSE(report.ok());
            EXPECT_EQ(report.error().code, ErrorCode::Cancelled);
            EXPECT_LT(sink.last(), 1.0);
        }
    }
}

TEST(SurfaceFitTest, ProgressRisesToOne)
{
    const auto& scan = plainDrum();
    CancelAt sink(2.0); // never cancels
    auto report = fitSurface(scan.cloud, kindOptions(SurfaceKind::Cylinder), &sink);
    ASSERT_TRUE(report.ok());
    EXPECT_TRUE(sink.monotone());
    EXPECT_EQ(sink.last(), 1.0);
}

/** The surface as JSON text (17 significant digits): equal strings, bitwise equal surfaces. */
std::string surfaceText(const cloud::PointCloud& cloud, SurfaceKind kind, unsigned threads)
{
    return fitOk(cloud, kindOptions(kind, threads)).surface.toJson().dump();
}

TEST(SurfaceFitTest, CylinderDoesNotDependOnTheThreadCount)
{
    const auto& drum = flutedDrum();
    const std::string one = surfaceText(drum.cloud, SurfaceKind::Cylinder, 1);
    EXPECT_EQ(surfaceText(drum.cloud, SurfaceKind::Cylinder, 2), one);
    EXPECT_EQ(surfaceText(drum.cloud, SurfaceKind::Cylinder, 3), one);
}

TEST(SurfaceFitTest, ConeDoesNotDependOnTheThreadCount)
{
    const test::ConeCloud cone = test::coneCloud(0.5, 0.4, 0.6, 50000, 0.0003, 0.05, 22);
    EXPECT_EQ(surfaceText(cone.cloud, SurfaceKind::Cone, 2), surfaceText(cone.cloud, SurfaceKind::Cone, 1));
}

TEST(SurfaceFitTest, RevolutionDoesNotDependOnTheThreadCount)
{
    const auto& omph = omphalos();
    EXPECT_EQ(surfaceText(omph.cloud, SurfaceKind::Revolution, 2), surfaceText(omph.cloud, SurfaceKind::Revolution, 1));
}

TEST(SurfaceFitTest, AnotherSeedSamplesOtherPointsForAsGoodAFit)
{
    // More points than the seed's sample (100 k): the seed picks which.
    const test::ConeCloud cone = test::coneCloud(0.5, 0.5, 0.5, 200000, 0.0003, 0.05, 23);
    FitOptions other = kindOptions(SurfaceKind::Cylinder);
    other.seed = 2;
    const Surface a = fitOk(cone.cloud, kindOptions(SurfaceKind::Cylinder)).surface;
    const Surface b = fitOk(cone.cloud, other).surface;
    EXPECT_NE(a.toJson().dump(), b.toJson().dump());
    EXPECT_LT(angleDegrees(a.axis().direction, b.axis().direction), 0.002);
    EXPECT_LT(axisDistance(a.axis(), b.axis(), 0.5), 2e-5);
    EXPECT_NEAR(a.radius(), b.radius(), 2e-5);
}

TEST(SurfaceFitTest, HappyBuddhaFitsAsACylinderAndAsARevolution)
{
    SKIP_WITHOUT_SHARED_DATA();
    auto loaded = cloud::loadPointCloud(test::sharedData() / "scans" / "happy_buddha_1.1M.ply");
    ASSERT_TRUE(loaded.ok()) << loaded.error().message;
    // Every eighth point (137 k) keeps the test quick; the whole scan fits alike (docs/benchmarks.md).
    cloud::PointCloud cloud;
    cloud.origin = loaded->origin;
    cloud.source = loaded->source;
    for (std::size_t i = 0; i < loaded->size(); i += 8)
        cloud.positions.insert(cloud.positions.end(), &loaded->positions[3 * i], &loaded->positions[3 * i + 3]);
    // A statuette about 0.2 m tall standing along +y: column-like, far from a cylinder.
    for (SurfaceKind kind : {SurfaceKind::Cylinder, SurfaceKind::Revolution}) {
        const FitReport report = fitOk(cloud, kindOptions(kind));
        EXPECT_GT(report.surface.axis().direction.y(), 0.99) << surfaceKindName(kind);
        EXPECT_GT(report.surface.referenceRadius(), 0.02);
        EXPECT_LT(report.surface.referenceRadius(), 0.04);
    }
}

} // namespace
} // namespace stylos::core::unroll
