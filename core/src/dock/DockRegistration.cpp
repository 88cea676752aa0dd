#include "stylos/core/dock/DockRegistration.h"

#include "stylos/core/dock/FluteModel.h"
#include "stylos/core/dock/FluteSnap.h"

#include <Eigen/Dense>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <numbers>

namespace stylos::core::dock {
namespace {

using Vector6d = Eigen::Matrix<double, 6, 1>;
using Matrix6d = Eigen::Matrix<double, 6, 6>;

constexpr double kTukey = 4.685;             ///< Tukey biweight width, in robust σ
constexpr double kMad = 1.482602218505602;   ///< MAD → σ for Gaussian residuals
constexpr double kEnvelopeStart = 0.03;      ///< metres: the envelope stage's first τ (at least 4 depths)
constexpr double kConverged = 1e-8;          ///< metres: a step that moves no point more than this
constexpr double kMinStrength = 0.15;        ///< snap strength: noise gives about 1/√n
constexpr std::size_t kMinInliers = 200;
/// Smallest eigenvalue of the scaled (correlation) normal matrix, as a share of the largest, for a direction to count
/// as determined. Measured: 0.14–0.20 on generated fragments against cylinder guides once z is out; 1.1e-3 for the
/// radius–height pair against a drum tapering 12 mm/m, where the data fix only r + slope·z (a radius error of 0.05 mm
/// would move z by 4 mm).
constexpr double kUnobservable = 1e-2;
constexpr int kEnvelopeIterations = 40;

Error invalid(const cloud::PointCloud& cloud, const std::string& problem)
{
    return Error::at(ErrorCode::InvalidArgument, cloud.source.empty() ? "<memory>" : cloud.source, {}, problem);
}

std::string millimetres(double metres)
{
    char text[32];
    std::snprintf(text, sizeof text, "%.1f mm", metres * 1e3);
    return text;
}

enum class Stage { Envelope, Profile };

/** The fragment's sample and its current placement in the drum frame. */
struct Problem {
    std::vector<Eigen::Vector3d> local; ///< cloud-local
    Eigen::Isometry3d toFrame;          ///< cloud-local → drum frame
    const FluteModel& model;
    double scale;                       ///< of the angular unknowns: the mean radius (their columns in metres)
    std::vector<Eigen::Vector3d> q;     ///< current drum-frame positions
    std::vector<double> e, w;           ///< residual and weight per point

    void place()
    {
        q.resize(local.size());
        for (std::size_t i = 0; i < local.size(); ++i) q[i] = toFrame * local[i];
    }

    /** Residual of point @p p and its gradient with respect to p. */
    double residual(Stage stage, const Eigen::Vector3d& p, Eigen::Vector3d& gradient) const
    {
        if (stage == Stage::Envelope) { // the cylinder (cone) of the mean radius
            const double rho = std::max(std::hypot(p.x(), p.y()), 1e-12);
            const double kZ = model.taper() * model.meanRadius(), g = std::sqrt(1.0 + kZ * kZ);
            gradient = Eigen::Vector3d(p.x() / rho, p.y() / rho, -kZ) / g;
            return (rho - model.scaleAt(p.z()) * model.meanRadius()) / g;
        }
        return model.distance(p, &gradient);
    }

    /** Residuals at the current placement, weights for width @p tau. */
    void evaluate(Stage stage, double tau)
    {
        e.resize(q.size());
        w.resize(q.size());
        Eigen::Vector3d gradient;
        for (std::size_t i = 0; i < q.size(); ++i) {
            e[i] = residual(stage, q[i], gradient);
            const double u = e[i] / tau;
            w[i] = std::abs(u) < 1.0 ? (1.0 - u * u) * (1.0 - u * u) : 0.0;
        }
    }

    std::size_t inliers() const
    {
        return std::size_t(std::count_if(w.begin(), w.end(), [](double v) { return v > 0.0; }));
    }

    /** Robust σ of the residuals within @p tau. */
    double robustSigma(double tau) const
    {
        std::vector<double> a;
        for (double v : e)
            if (std::abs(v) < tau) a.push_back(std::abs(v));
        if (a.empty()) return tau;
        const auto mid = a.begin() + std::ptrdiff_t(a.size() / 2);
        std::nth_element(a.begin(), mid, a.end());
        return kMad * *mid;
    }

    /** Weighted centroid of the inliers. */
    Eigen::Vector3d centre() const
    {
        Eigen::Vector3d c = Eigen::Vector3d::Zero();
        double sum = 0.0;
        for (std::size_t i = 0; i < q.size(); ++i) c += w[i] * q[i], sum += w[i];
        return sum > 0.0 ? Eigen::Vector3d(c / sum) : c;
    }

    /** Normal equations of the 6 unknowns (angular ones scaled) about centre @p c. */
    void normalEquations(Stage stage, const Eigen::Vector3d& c, Matrix6d& h, Vector6d& b) const
    {
        const double azimuth = std::atan2(c.y(), c.x());
        const Eigen::Vector3d ur(std::cos(azimuth), std::sin(azimuth), 0.0), ut(-ur.y(), ur.x(), 0.0);
        const Eigen::Vector3d ez = Eigen::Vector3d::UnitZ();
        h.setZero();
        b.setZero();
        Eigen::Vector3d gradient;
        for (std::size_t i = 0; i < q.size(); ++i) {
            if (w[i] <= 0.0) continue;
            const Eigen::Vector3d& p = q[i];
            residual(stage, p, gradient);
            const Eigen::Vector3d arm = p - c;
            Vector6d j;
            j[int(DockUnknown::Theta)] = gradient.dot(ez.cross(p)) / scale;
            j[int(DockUnknown::Z)] = gradient.z();
            j[int(DockUnknown::R)] = gradient.dot(ur);
            j[int(DockUnknown::Tangent)] = gradient.dot(ut);
            j[int(DockUnknown::TiltLean)] = gradient.dot(ut.cross(arm)) / scale;
            j[int(DockUnknown::TiltRoll)] = gradient.dot(ur.cross(arm)) / scale;
            h.selfadjointView<Eigen::Lower>().rankUpdate(j, w[i]);
            b += w[i] * e[i] * j;
        }
        h = h.selfadjointView<Eigen::Lower>();
    }

    /** The rigid motion of increment @p delta (angular unknowns in radians) about centre @p c. */
    static Eigen::Isometry3d motion(const Vector6d& delta, const Eigen::Vector3d& c)
    {
        const double azimuth = std::atan2(c.y(), c.x());
        const Eigen::Vector3d ur(std::cos(azimuth), std::sin(azimuth), 0.0), ut(-ur.y(), ur.x(), 0.0);
        const Eigen::Vector3d omega = delta[int(DockUnknown::TiltLean)] * ut + delta[int(DockUnknown::TiltRoll)] * ur;
        Eigen::Isometry3d tilt = Eigen::Isometry3d::Identity();
        if (omega.norm() > 0.0)
            tilt = Eigen::Translation3d(c) * Eigen::AngleAxisd(omega.norm(), omega.normalized()) * Eigen::Translation3d(-c);
        const Eigen::Vector3d shift = delta[int(DockUnknown::Z)] * Eigen::Vector3d::UnitZ() +
                                      delta[int(DockUnknown::R)] * ur + delta[int(DockUnknown::Tangent)] * ut;
        return Eigen::Isometry3d(Eigen::AngleAxisd(delta[int(DockUnknown::Theta)], Eigen::Vector3d::UnitZ())) *
               Eigen::Translation3d(shift) * tilt;
    }
};

/** The free unknowns of @p h: not in @p held, with a column, and not in a (near) null direction of
 *  the scaled matrix; the unobservable ones are added to @p unobservable. */
std::vector<int> freeUnknowns(const Matrix6d& h, const std::array<bool, DockUnknowns>& held,
                              std::vector<DockUnknown>* unobservable)
{
    std::vector<int> free;
    double largest = 0.0;
    for (int k = 0; k < DockUnknowns; ++k) largest = std::max(largest, h(k, k));
    for (int k = 0; k < DockUnknowns; ++k) {
        if (held[std::size_t(k)]) continue;
        if (!(h(k, k) > 1e-12 * largest)) {
            if (unobservable) unobservable->push_back(DockUnknown(k));
            continue;
        }
        free.push_back(k);
    }
    for (;;) { // drop the unknown that dominates a null direction, until none is left
        const int n = int(free.size());
        if (n == 0) break;
        Eigen::MatrixXd m(n, n);
        for (int a = 0; a < n; ++a)
            for (int c = 0; c < n; ++c) m(a, c) = h(free[a], free[c]) / std::sqrt(h(free[a], free[a]) * h(free[c], free[c]));
        const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> eigen(m);
        if (eigen.eigenvalues()[0] > kUnobservable * eigen.eigenvalues()[n - 1]) break;
        int worst = 0;
        const double largestShare = eigen.eigenvectors().col(0).cwiseAbs().maxCoeff(&worst);
        // The height is what flutes cannot fix: when it shares the near-null direction (on a tapering drum, with the
        // radius: r + slope·z is all the cone constrains), it is the one left where the user put it.
        for (int a = 0; a < n; ++a)
            if (free[std::size_t(a)] == int(DockUnknown::Z) && std::abs(eigen.eigenvectors()(a, 0)) >= 0.5 * largestShare)
                worst = a;
        if (unobservable) unobservable->push_back(DockUnknown(free[std::size_t(worst)]));
        free.erase(free.begin() + worst);
    }
    return free;
}

/** One Gauss–Newton step over the free unknowns; the largest displacement it causes (metres), or −1
 *  when nothing is free. */
double step(Problem& p, Stage stage, const std::array<bool, DockUnknowns>& held)
{
    const Eigen::Vector3d c = p.centre();
    Matrix6d h;
    Vector6d b;
    p.normalEquations(stage, c, h, b);
    const std::vector<int> free = freeUnknowns(h, held, nullptr);
    if (free.empty()) return -1.0;
    const int n = int(free.size());
    Eigen::MatrixXd a(n, n);
    Eigen::VectorXd rhs(n);
    for (int i = 0; i < n; ++i) {
        rhs[i] = -b[free[i]];
        for (int k = 0; k < n; ++k) a(i, k) = h(free[i], free[k]);
    }
    const Eigen::VectorXd x = a.ldlt().solve(rhs);
    if (!x.allFinite()) return -1.0;
    Vector6d delta = Vector6d::Zero();
    for (int i = 0; i < n; ++i) delta[free[i]] = x[i];
    double extent = 0.0;
    for (const Eigen::Vector3d& q : p.q) extent = std::max(extent, (q - c).norm());
    const double moved = std::abs(x.cwiseAbs().maxCoeff()) * std::max(1.0, (p.scale + extent) / p.scale);
    for (int k : {int(DockUnknown::Theta), int(DockUnknown::TiltLean), int(DockUnknown::TiltRoll)}) delta[k] /= p.scale;
    p.toFrame = Problem::motion(delta, c) * p.toFrame;
    p.place();
    return moved;
}

} // namespace

const char* dockUnknownName(DockUnknown unknown)
{
    switch (unknown) {
    case DockUnknown::Theta: return "theta";
    case DockUnknown::Z: return "z";
    case DockUnknown::R: return "r";
    case DockUnknown::Tangent: return "tangent";
    case DockUnknown::TiltLean: return "tilt_lean";
    case DockUnknown::TiltRoll: return "tilt_roll";
    }
    return "?";
}

std::vector<DockUnknown> dockUnknownsFromName(std::string_view name)
{
    if (name == "tilt") return {DockUnknown::TiltLean, DockUnknown::TiltRoll};
    // The fragment's place round the drum: the turn about the axis and the sideways slide that, on a fragment, stands
    // for the same motion (with the turn alone locked the slide carried it to the next flute anyway).
    if (name == "theta") return {DockUnknown::Theta, DockUnknown::Tangent};
    for (int k = 0; k < DockUnknowns; ++k)
        if (name == dockUnknownName(DockUnknown(k))) return {DockUnknown(k)};
    return {};
}

Result<DockResult> dockFragment(const cloud::PointCloud& fragment, const DrumGuides& guides,
                                const Eigen::Isometry3d& start, const DockOptions& options, ProgressSink* progress,
                                DockFailure* failure)
{
    const auto started = std::chrono::steady_clock::now();
    DockFailure ignored;
    DockFailure& why = failure ? *failure : ignored;
    why = {};
    const auto failed = [&why](DockFailure::Kind kind) -> DockFailure& {
        why.kind = kind;
        return why;
    };
    auto model = FluteModel::fromGuides(guides);
    if (!model) return invalid(fragment, model.error().message);
    const DrumFrame frame(guides);
    const std::size_t n = fragment.size();
    if (n < kMinInliers) {
        failed(DockFailure::Kind::TooFewPoints).points = n;
        return invalid(fragment, std::to_string(n) + " points: too few to dock (at least 200)");
    }
    if (!start.matrix().allFinite()) return invalid(fragment, "the starting pose is not finite");

    Eigen::Isometry3d frameOfWorld = Eigen::Isometry3d::Identity();
    frameOfWorld.linear() = frame.rows;
    frameOfWorld.translation() = -frame.rows * frame.origin;
    Problem p{{}, frameOfWorld * start * Eigen::Translation3d(fragment.origin), *model, model->meanRadius(), {}, {}, {}};
    const std::size_t stride = std::max<std::size_t>(1, (n + options.maxPoints - 1) / options.maxPoints);
    for (std::size_t i = 0; i < n; i += stride) {
        const Eigen::Vector3d v = fragment.local(i);
        if (v.allFinite()) p.local.push_back(v);
    }
    p.place();
    const Eigen::Isometry3d startFrame = p.toFrame;
    DockResult result;
    auto cancelled = [&] { return progress && progress->isCancelRequested(); };

    // 1. Envelope: the cylinder of the mean radius fixes r, tangent and the tilts.
    std::array<bool, DockUnknowns> held = options.locked;
    std::array<bool, DockUnknowns> envelopeHeld = held;
    envelopeHeld[int(DockUnknown::Theta)] = envelopeHeld[int(DockUnknown::Z)] = true;
    const double depth = model->depth();
    double tau = std::max(kEnvelopeStart, 4.0 * depth);
    p.evaluate(Stage::Envelope, tau);
    if (p.inliers() < kMinInliers) {
        failed(DockFailure::Kind::TooFar).points = p.inliers();
        why.reachM = tau;
        return invalid(fragment, "the starting pose is too far from the drum: " + std::to_string(p.inliers()) +
                                     " points lie within " + millimetres(tau) + " of its surface (at least 200 needed)");
    }
    for (int it = 0; it < kEnvelopeIterations; ++it) {
        if (cancelled()) return Error{ErrorCode::Cancelled, fragment.source + ": docking cancelled"};
        const double moved = step(p, Stage::Envelope, envelopeHeld);
        ++result.iterations;
        const double next = std::max(1.5 * depth, std::min(tau, 3.0 * p.robustSigma(tau)));
        const bool settled = std::abs(next - tau) < 0.01 * tau;
        tau = next;
        p.evaluate(Stage::Envelope, tau);
        if (p.inliers() < kMinInliers) {
            failed(DockFailure::Kind::LeftTheDrum);
            return invalid(fragment, "the starting pose is too far from the drum: the fragment's outer face does not "
                                     "meet the drum's surface");
        }
        if ((moved < 1e-6 || moved < 0) && settled) break;
    }
    if (progress) progress->update(0.3);

    // 2. Flute snap.
    if (options.snap && !held[int(DockUnknown::Theta)]) {
        std::vector<Eigen::Vector3d> inliers;
        for (std::size_t i = 0; i < p.q.size(); ++i)
            if (p.w[i] > 0.0) inliers.push_back(p.q[i]);
        const FluteSnap snap = snapToFlutes(inliers, *model, 2.0 * p.robustSigma(tau));
        result.snapStrength = snap.strength;
        if (snap.strength < kMinStrength) {
            char text[160];
            std::snprintf(text, sizeof text,
                          "no readable flutes on the fragment: its flute signal is %.2f (at least %.2f needed; "
                          "noise gives about %.2f)", snap.strength, kMinStrength, 1.0 / std::sqrt(double(std::max<std::size_t>(snap.points, 1))));
            DockFailure& noFlutes = failed(DockFailure::Kind::NoFlutes);
            noFlutes.strength = snap.strength;
            noFlutes.needed = kMinStrength;
            return invalid(fragment, text);
        }
        result.snapRotation = snap.rotation;
        p.toFrame = Eigen::Isometry3d(Eigen::AngleAxisd(snap.rotation, Eigen::Vector3d::UnitZ())) * p.toFrame;
        p.place();
    }
    if (progress) progress->update(0.4);

    // 3. Profile: every free unknown against the flutes, τ down to the noise.
    tau = 2.0 * depth;
    p.evaluate(Stage::Profile, tau);
    bool converged = false;
    for (int it = 0; it < options.maxIterations; ++it) {
        if (cancelled()) return Error{ErrorCode::Cancelled, fragment.source + ": docking cancelled"};
        const double moved = step(p, Stage::Profile, held);
        ++result.iterations;
        const double next = std::min(tau, std::max(1e-5, kTukey * p.robustSigma(tau)));
        const bool settled = std::abs(next - tau) < 0.01 * tau;
        tau = next;
        p.evaluate(Stage::Profile, tau);
        if (p.inliers() < kMinInliers) {
            failed(DockFailure::Kind::LostOuterFace).points = p.inliers();
            return invalid(fragment, "docking lost the fragment's outer face (fewer than 200 points on the flutes)");
        }
        if (progress) progress->update(0.4 + 0.6 * double(it + 1) / options.maxIterations);
        if (moved < kConverged && settled) {
            converged = true;
            break;
        }
    }
    if (!converged) {
        DockFailure& f = failed(DockFailure::Kind::NotConverged);
        f.iterations = options.maxIterations;
        f.thetaLocked = options.locked[std::size_t(DockUnknown::Theta)];
        return invalid(fragment, "the registration did not converge in " + std::to_string(options.maxIterations) +
                                     " iterations" +
                                     (f.thetaLocked ? std::string("; θ is locked and may hold it off its flute: free θ, or "
                                                                  "start it on its flute")
                                                    : std::string()));
    }

    // What the data fix, and how well.
    const Eigen::Vector3d c = p.centre();
    Matrix6d h;
    Vector6d b;
    p.normalEquations(Stage::Profile, c, h, b);
    const std::vector<int> free = freeUnknowns(h, held, &result.unobservable);
    double we2 = 0.0, sw = 0.0, e2 = 0.0;
    std::size_t in = 0;
    for (std::size_t i = 0; i < p.q.size(); ++i)
        if (p.w[i] > 0.0) we2 += p.w[i] * p.e[i] * p.e[i], sw += p.w[i], e2 += p.e[i] * p.e[i], ++in;
    result.inliers = in;
    result.rms = in ? std::sqrt(e2 / double(in)) : 0.0;
    if (!free.empty()) {
        const int k = int(free.size());
        Eigen::MatrixXd a(k, k);
        for (int i = 0; i < k; ++i)
            for (int j = 0; j < k; ++j) a(i, j) = h(free[i], free[j]);
        const double s2 = sw > double(k) ? we2 / (sw - double(k)) : 0.0;
        const Eigen::MatrixXd cov = s2 * a.inverse();
        for (int i = 0; i < k; ++i) {
            const DockUnknown u = DockUnknown(free[i]);
            const bool angular = u == DockUnknown::Theta || u == DockUnknown::TiltLean || u == DockUnknown::TiltRoll;
            result.uncertainty.push_back({u, std::sqrt(std::max(0.0, cov(i, i))) / (angular ? p.scale : 1.0)});
        }
    }
    // Rotation about the axis from start to end: the turn that best carries the points' start places onto their
    // docked places about the axis (least squares, in the frame's xy plane). A fragment's slide along the surface
    // counts, as it moves the fragment round the drum; a whole drum's does not (its centre lies on the axis,
    // whose azimuth is noise).
    double across = 0.0, along = 0.0;
    for (const Eigen::Vector3d& v : p.local) {
        const Eigen::Vector3d a0 = startFrame * v, a1 = p.toFrame * v;
        across += a0.x() * a1.y() - a0.y() * a1.x();
        along += a0.x() * a1.x() + a0.y() * a1.y();
    }
    const double turn = std::atan2(across, along);
    result.fluteShift = turn / model->pitch();

    result.pose = frameOfWorld.inverse() * p.toFrame * Eigen::Translation3d(-fragment.origin);
    if (progress) progress->update(1.0);
    result.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
    return result;
}

} // namespace stylos::core::dock
