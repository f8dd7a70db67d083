#include "model/reference/strip_rings.h"

#include "model/reference/initial_strip.h"
#include "model/reference/strip_sheet.h"

#include <Eigen/Dense>

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <stdexcept>
#include <tuple>
#include <utility>

namespace devsurf::model::reference {

namespace {

constexpr double kTwoPi = 6.283185307179586;
// The closed curve's distance from the centre as 1 + Σ aₖ cos kθ + bₖ sin kθ for k = 2 … this
// + 1 (the first harmonic is a shift of the centre).
constexpr int kFourierTerms = 4;
constexpr int kFitRounds = 8;
// The rings the axes are compared with; a point's distance from the centre line is explained
// by them within kExplainedRhos ρ or kExplainedFraction of the distance, whichever is larger.
constexpr int kAxisTrialRings = 4;
constexpr int kAxisRefinements = 2;
constexpr double kExplainedRhos = 2.0;
constexpr double kExplainedFraction = 0.1;
// A fitted curve that comes nearer its centre than this fraction of its mean distance is
// refitted as a circle.
constexpr double kNearestCurveFraction = 0.2;

// A principal axis and the plane across it: e1 × e2 = axis.
struct AxisFrame {
    Vec3 origin;
    Vec3 axis;
    Vec3 e1;
    Vec3 e2;
};

struct Local {
    double z = 0.0;
    double x = 0.0;
    double y = 0.0;
};

// Heights z0 + j · step, j = 0 … lines − 1, with a value per line interpolated linearly
// between them (and held beyond the ends).
struct Lines {
    double z0 = 0.0;
    double step = 1.0;
    int count = 2;

    // The line below z and the weight of the line above it.
    std::pair<int, double> place(double z) const {
        const double t = std::clamp((z - z0) / step, 0.0, static_cast<double>(count - 1));
        const int j = std::min(static_cast<int>(std::floor(t)), count - 2);
        return {j, t - j};
    }
    double at(const std::vector<double>& values, double z) const {
        const auto [j, f] = place(z);
        return values[j] * (1.0 - f) + values[j + 1] * f;
    }
};

// The centre line: per line the hat-weighted mean of the points' coordinates across the axis;
// a line no point is near takes its nearest neighbour's.
void centres(const std::vector<Local>& local, const Lines& lines, std::vector<double>& cx,
             std::vector<double>& cy) {
    std::vector<double> weight(lines.count, 0.0);
    cx.assign(lines.count, 0.0);
    cy.assign(lines.count, 0.0);
    for (const Local& p : local) {
        const auto [j, f] = lines.place(p.z);
        weight[j] += 1.0 - f;
        cx[j] += (1.0 - f) * p.x;
        cy[j] += (1.0 - f) * p.y;
        weight[j + 1] += f;
        cx[j + 1] += f * p.x;
        cy[j + 1] += f * p.y;
    }
    int known = -1;
    for (int j = 0; j < lines.count; ++j) {
        if (weight[j] > 1e-9) {
            cx[j] /= weight[j];
            cy[j] /= weight[j];
            if (known < 0) {
                for (int k = 0; k < j; ++k) {
                    cx[k] = cx[j];
                    cy[k] = cy[j];
                }
            }
            known = j;
        } else if (known >= 0) {
            cx[j] = cx[known];
            cy[j] = cy[known];
        }
    }
}

std::vector<Local> localPoints(const std::vector<Vec3>& points, const AxisFrame& frame) {
    std::vector<Local> local;
    local.reserve(points.size());
    for (const Vec3& p : points) {
        const Vec3 d = p - frame.origin;
        local.push_back({dot(d, frame.axis), dot(d, frame.e1), dot(d, frame.e2)});
    }
    return local;
}

// One layer all around the centre line (the check tubeAxis documents).
bool closesAround(const std::vector<Local>& local, const std::vector<Vec3>& normals,
                  const AxisFrame& frame, double zLow, double zHigh, double rho) {
    Lines lines;
    lines.count =
        std::clamp(static_cast<int>(std::lround((zHigh - zLow) / (4.0 * rho))), 1, 16) + 1;
    lines.z0 = zLow;
    lines.step = std::max(zHigh - zLow, 1e-9) / (lines.count - 1);
    std::vector<double> cx;
    std::vector<double> cy;
    centres(local, lines, cx, cy);
    std::vector<double> radius(local.size());
    std::vector<double> theta(local.size());
    double meanRadius = 0.0;
    for (std::size_t i = 0; i < local.size(); ++i) {
        const double x = local[i].x - lines.at(cx, local[i].z);
        const double y = local[i].y - lines.at(cy, local[i].z);
        radius[i] = std::hypot(x, y);
        theta[i] = std::atan2(y, x);
        meanRadius += radius[i] / static_cast<double>(local.size());
    }
    if (!(meanRadius > 2.0 * rho)) {
        return false;
    }
    const int around =
        std::max(kTubeAngularBins, static_cast<int>(std::ceil(kTwoPi * meanRadius / (2.0 * rho))));
    const auto bin = [](double angle, int bins) {
        return std::clamp(static_cast<int>(std::floor((angle + kTwoPi / 2) / kTwoPi * bins)), 0,
                          bins - 1);
    };
    struct Cell {
        double low = std::numeric_limits<double>::max();
        double high = std::numeric_limits<double>::lowest();
        double slope = 0.0;
    };
    std::map<std::pair<int, long>, Cell> cells;
    // Every slab between two lines holds points all around.
    std::vector<std::vector<bool>> angles(lines.count - 1,
                                          std::vector<bool>(kTubeAngularBins, false));
    const double cosLimit = std::cos(kPatchNormalAngle);
    std::size_t facing = 0;
    for (std::size_t i = 0; i < local.size(); ++i) {
        const double length = normals[i].norm();
        if (!(length > 0.0) || !std::isfinite(length)) {
            return false;
        }
        const Vec3 away = frame.e1 * std::cos(theta[i]) + frame.e2 * std::sin(theta[i]);
        const double c = std::min(1.0, std::abs(dot(normals[i], away)) / length);
        facing += c >= cosLimit ? 1 : 0;
        angles[lines.place(local[i].z).first][bin(theta[i], kTubeAngularBins)] = true;
        Cell& cell = cells[{bin(theta[i], around),
                            std::lround(std::floor((local[i].z - zLow) / (2.0 * rho)))}];
        cell.low = std::min(cell.low, radius[i]);
        cell.high = std::max(cell.high, radius[i]);
        cell.slope =
            std::max(cell.slope, std::sqrt(std::max(0.0, 1.0 - c * c)) / std::max(c, cosLimit));
    }
    if (static_cast<double>(facing) < kTubeNormalShare * static_cast<double>(local.size()) ||
        !std::all_of(angles.begin(), angles.end(), [](const std::vector<bool>& slab) {
            return std::all_of(slab.begin(), slab.end(), [](bool b) { return b; });
        })) {
        return false;
    }
    const double diagonal = 2.0 * rho * std::sqrt(2.0);
    return std::all_of(cells.begin(), cells.end(), [&](const auto& entry) {
        const Cell& cell = entry.second;
        return cell.high - cell.low <= diagonal * cell.slope + rho;
    });
}

// The rings' curves: the centres and scales at count + 1 lines, and the closed curve
// C(θ) = c(θ) (cos θ e1 + sin θ e2) they are scaled copies of.
struct RingFit {
    Lines lines;
    std::vector<double> cx, cy, scale;
    std::vector<double>
        heights; // of the curves: the lines', the ends' shortened where the shape closes
    Eigen::VectorXd fourier; // c(θ) = fourier · (1, cos 2θ, sin 2θ, cos 3θ, …)
    double squaredError = std::numeric_limits<double>::infinity();
    std::size_t explained = 0; // points whose distance the fit gives within explainedWithin

    double c(double theta) const {
        double value = fourier(0);
        for (Eigen::Index h = 1; 2 * h < fourier.size(); ++h) {
            const double k = static_cast<double>(h + 1);
            value +=
                fourier(2 * h - 1) * std::cos(k * theta) + fourier(2 * h) * std::sin(k * theta);
        }
        return value;
    }
};

// ρ at the lines and c(θ) fitted to the points' distances r ≈ ρ(z) c(θ) from the centre line
// by alternating least squares, the centres moved by the same least squares (a shift (dx, dy)
// changes r by about dx cos θ + dy sin θ; c has no first harmonic, which the shift is). ρ's and
// the shifts' second differences are held a little towards 0, so that a line no point is near
// stays determined; c's constant term is 1.
RingFit fitRings(const std::vector<Local>& local, double zLow, double zHigh, int count,
                 double beyond, int terms, double explainedWithin) {
    RingFit fit;
    fit.lines.count = count + 1;
    fit.lines.z0 = zLow - beyond;
    fit.lines.step = (zHigh - zLow + 2.0 * beyond) / count;
    centres(local, fit.lines, fit.cx, fit.cy);
    const auto n = static_cast<Eigen::Index>(local.size());
    const Eigen::Index lines = count + 1;
    Eigen::VectorXd r(n);
    std::vector<double> theta(local.size());
    std::vector<std::pair<int, double>> place(local.size());
    for (std::size_t i = 0; i < local.size(); ++i) {
        place[i] = fit.lines.place(local[i].z);
    }
    const auto measure = [&] {
        for (std::size_t i = 0; i < local.size(); ++i) {
            const double x = local[i].x - fit.lines.at(fit.cx, local[i].z);
            const double y = local[i].y - fit.lines.at(fit.cy, local[i].z);
            r(static_cast<Eigen::Index>(i)) = std::hypot(x, y);
            theta[i] = std::atan2(y, x);
        }
    };
    // c's columns: the constant, then cos kθ and sin kθ for k = 2 … terms + 1.
    const Eigen::Index columns = 1 + 2 * terms;
    fit.fourier = Eigen::VectorXd::Zero(columns);
    fit.fourier(0) = 1.0;
    const double smooth = 1e-3 * std::sqrt(static_cast<double>(n) / lines);
    std::vector<double> scale;
    for (int round = 0; round < kFitRounds; ++round) {
        measure();
        // ρ and the centres' shifts at the lines, c held.
        Eigen::MatrixXd a = Eigen::MatrixXd::Zero(n + 3 * (count - 1), 3 * lines);
        Eigen::VectorXd b = Eigen::VectorXd::Zero(a.rows());
        for (Eigen::Index i = 0; i < n; ++i) {
            const std::size_t k = static_cast<std::size_t>(i);
            const auto [j, f] = place[k];
            const double c = fit.c(theta[k]);
            const double w[2] = {1.0 - f, f};
            for (int side = 0; side < 2; ++side) {
                a(i, j + side) = w[side] * c;
                a(i, lines + j + side) = w[side] * std::cos(theta[k]);
                a(i, 2 * lines + j + side) = w[side] * std::sin(theta[k]);
            }
            b(i) = r(i);
        }
        for (int part = 0; part < 3; ++part) {
            for (int k = 1; k < count; ++k) {
                const Eigen::Index row = n + part * (count - 1) + k - 1;
                a(row, part * lines + k - 1) = smooth;
                a(row, part * lines + k) = -2.0 * smooth;
                a(row, part * lines + k + 1) = smooth;
            }
        }
        const Eigen::VectorXd solution = a.colPivHouseholderQr().solve(b);
        scale.assign(solution.data(), solution.data() + lines);
        for (Eigen::Index j = 0; j < lines; ++j) {
            fit.cx[static_cast<std::size_t>(j)] += solution(lines + j);
            fit.cy[static_cast<std::size_t>(j)] += solution(2 * lines + j);
        }
        measure();
        // c, ρ held.
        Eigen::MatrixXd shape(n, columns);
        for (Eigen::Index i = 0; i < n; ++i) {
            const std::size_t k = static_cast<std::size_t>(i);
            const double rho = fit.lines.at(scale, local[k].z);
            shape(i, 0) = rho;
            for (int h = 1; h <= terms; ++h) {
                shape(i, 2 * h - 1) = rho * std::cos((h + 1) * theta[k]);
                shape(i, 2 * h) = rho * std::sin((h + 1) * theta[k]);
            }
        }
        const Eigen::VectorXd coefficients = shape.colPivHouseholderQr().solve(r);
        if (!(std::abs(coefficients(0)) > 1e-9)) {
            scale.clear();
            break;
        }
        for (double& s : scale) {
            s *= coefficients(0);
        }
        fit.fourier = coefficients / coefficients(0);
    }
    if (scale.empty()) {
        return fit;
    }
    fit.scale = scale;
    measure();
    fit.squaredError = 0.0;
    for (Eigen::Index i = 0; i < n; ++i) {
        const std::size_t k = static_cast<std::size_t>(i);
        const double model = fit.lines.at(fit.scale, local[k].z) * fit.c(theta[k]);
        const double e = r(i) - model;
        fit.squaredError += e * e;
        fit.explained += std::abs(e) <= std::max(explainedWithin, kExplainedFraction * model);
    }
    // The end rings shortened along their cones, so they stay on the cones fitted there: where
    // the shape closes (a sphere's pole) an end curve would come out below the smallest scale,
    // and the ring ends where its cone reaches it; where it stays open (a tube's rim), the ring
    // ends at the shape's end, the margin having served the fit only. Any other curve is held
    // at the smallest scale.
    const double smallest = kRingSmallestScale * *std::max_element(scale.begin(), scale.end());
    for (int j = 0; j <= count; ++j) {
        fit.heights.push_back(fit.lines.z0 + fit.lines.step * j);
    }
    for (const auto& [end, inner, rim] :
         {std::tuple{0, 1, zLow}, std::tuple{count, count - 1, zHigh}}) {
        const double outer = fit.scale[end];
        const double next = fit.scale[inner];
        double t = 1.0;
        if (outer < smallest && next > smallest) {
            t = (next - smallest) / (next - outer);
        } else if (outer >= smallest) {
            t = std::clamp((rim - fit.heights[inner]) / (fit.heights[end] - fit.heights[inner]),
                           0.0, 1.0);
        }
        if (t > 0.0 && t < 1.0) {
            const auto shorten = [&](std::vector<double>& v) {
                v[end] = v[inner] + t * (v[end] - v[inner]);
            };
            shorten(fit.heights);
            shorten(fit.cx);
            shorten(fit.cy);
            shorten(fit.scale);
        }
    }
    for (double& scaleAt : fit.scale) {
        scaleAt = std::max(scaleAt, smallest);
    }
    return fit;
}

// A fit whose curve stays clear of its centre: with kFourierTerms, else a circle.
RingFit fitClearRings(const std::vector<Local>& local, double zLow, double zHigh, int count,
                      double beyond, double explainedWithin) {
    RingFit fit = fitRings(local, zLow, zHigh, count, beyond, kFourierTerms, explainedWithin);
    double nearest = std::numeric_limits<double>::max();
    for (int k = 0; k < 360; ++k) {
        nearest = std::min(nearest, fit.c(kTwoPi * k / 360));
    }
    if (fit.scale.empty() || !(nearest > kNearestCurveFraction)) {
        fit = fitRings(local, zLow, zHigh, count, beyond, 0, explainedWithin);
    }
    return fit;
}

struct Choice {
    AxisFrame frame;
    std::vector<Local> local;
    double zLow = 0.0;
    double zHigh = 0.0;
};

std::optional<Choice> chooseAxis(const std::vector<Vec3>& points, const std::vector<Vec3>& normals,
                                 double rho) {
    if (points.size() < 3 || normals.size() != points.size() || !(rho > 0.0)) {
        return std::nullopt;
    }
    PrincipalFrame principal;
    try {
        principal = principalFrame(points);
    } catch (const std::invalid_argument&) {
        return std::nullopt;
    }
    std::optional<Choice> best;
    double bestError = std::numeric_limits<double>::infinity();
    for (int k = 0; k < 3; ++k) {
        Choice choice;
        choice.frame.origin = principal.centroid;
        choice.frame.axis = principal.axes[k];
        choice.frame.e1 = principal.axes[(k + 1) % 3];
        choice.frame.e2 = cross(choice.frame.axis, choice.frame.e1);
        choice.local = localPoints(points, choice.frame);
        choice.zLow = principal.low[k];
        choice.zHigh = principal.high[k];
        if (!(choice.zHigh - choice.zLow > 2.0 * rho) ||
            !closesAround(choice.local, normals, choice.frame, choice.zLow, choice.zHigh, rho)) {
            continue;
        }
        const RingFit fit = fitClearRings(choice.local, choice.zLow, choice.zHigh, kAxisTrialRings,
                                          0.0, kExplainedRhos * rho);
        if (static_cast<double>(fit.explained) <
            kTubeFitShare * static_cast<double>(points.size())) {
            continue; // not rings: a bulge or a limb stands off them
        }
        if (fit.squaredError < bestError) {
            bestError = fit.squaredError;
            best = std::move(choice);
        }
    }
    return best;
}

void pointExtent(const std::vector<Local>& local, double& low, double& high) {
    low = std::numeric_limits<double>::max();
    high = std::numeric_limits<double>::lowest();
    for (const Local& p : local) {
        low = std::min(low, p.z);
        high = std::max(high, p.z);
    }
}

// The frame turned so that its axis runs along the least-squares line through the fitted
// centres (the same sense, the same origin), e1 kept as near as it can be.
AxisFrame alongCentres(const AxisFrame& frame, const RingFit& fit) {
    std::vector<Vec3> centres;
    for (std::size_t j = 0; j < fit.cx.size(); ++j) {
        centres.push_back(frame.axis * fit.heights[j] + frame.e1 * fit.cx[j] +
                          frame.e2 * fit.cy[j]);
    }
    Vec3 mean;
    for (const Vec3& c : centres) {
        mean += c / static_cast<double>(centres.size());
    }
    Eigen::Matrix3d scatter = Eigen::Matrix3d::Zero();
    for (const Vec3& c : centres) {
        const Eigen::Vector3d d(c.x - mean.x, c.y - mean.y, c.z - mean.z);
        scatter += d * d.transpose();
    }
    const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eigen(scatter);
    const Eigen::Vector3d top = eigen.eigenvectors().col(2);
    Vec3 axis(top(0), top(1), top(2));
    if (!(axis.norm() > 0.5) || !std::isfinite(axis.norm())) {
        return frame;
    }
    axis = axis / axis.norm();
    if (dot(axis, frame.axis) < 0.0) {
        axis = -axis;
    }
    Vec3 e1 = frame.e1 - axis * dot(frame.e1, axis);
    if (!(e1.norm() > 1e-6)) {
        return frame;
    }
    AxisFrame turned;
    turned.origin = frame.origin;
    turned.axis = axis;
    turned.e1 = e1 / e1.norm();
    turned.e2 = cross(turned.axis, turned.e1);
    return turned;
}

} // namespace

std::optional<Vec3> tubeAxis(const std::vector<Vec3>& points, const std::vector<Vec3>& normals,
                             double rho) {
    if (std::optional<Choice> choice = chooseAxis(points, normals, rho)) {
        return choice->frame.axis;
    }
    return std::nullopt;
}

CompositeSurface initialStripRings(const std::vector<Vec3>& points,
                                   const std::vector<Vec3>& normals, double rho, int count,
                                   const SplineSpace& space, double margin,
                                   const std::vector<Vec3>& whole) {
    if (count < 1) {
        throw std::invalid_argument("lay at least one ring");
    }
    if (space.controlPointCount(false) < 2 || !(margin >= 0.0)) {
        throw std::invalid_argument("invalid spline space or margin");
    }
    const std::optional<Choice> choice = chooseAxis(points, normals, rho);
    if (!choice) {
        throw std::invalid_argument("the points do not close around an axis");
    }
    // The principal axis of thinned points may lean (1.3° on a thinned tube): the fitted
    // centres then drift across it, and the end curves would lie askew to a straight rim. The
    // axis is turned onto the line through the centres, kAxisRefinements times.
    AxisFrame frame = choice->frame;
    std::vector<Local> local = choice->local;
    for (int round = 0; round < kAxisRefinements; ++round) {
        double low = 0.0;
        double high = 0.0;
        pointExtent(local, low, high);
        const RingFit trial = fitClearRings(local, low, high, std::max(count, kAxisTrialRings), 0.0,
                                            kExplainedRhos * rho);
        if (trial.scale.empty()) {
            break;
        }
        frame = alongCentres(frame, trial);
        local = localPoints(points, frame);
    }
    // Along the whole shape, or else beyond the points by at least ρ: thinned points may stop
    // short of the shape's ends by up to ρ.
    double zLow = 0.0;
    double zHigh = 0.0;
    pointExtent(local, zLow, zHigh);
    double least = rho;
    if (!whole.empty()) {
        zLow = std::numeric_limits<double>::max();
        zHigh = std::numeric_limits<double>::lowest();
        for (const Vec3& p : whole) {
            const double z = dot(p - frame.origin, frame.axis);
            if (std::isfinite(z)) {
                zLow = std::min(zLow, z);
                zHigh = std::max(zHigh, z);
            }
        }
        least = 0.0;
        if (!(zHigh > zLow)) {
            throw std::invalid_argument("the whole shape has no extent along the axis");
        }
    }
    zLow -= least;
    zHigh += least;
    const double beyond = std::max(margin * (zHigh - zLow), 0.0);
    const RingFit fit = fitClearRings(local, zLow, zHigh, count, beyond, kExplainedRhos * rho);
    if (fit.scale.empty()) {
        throw std::invalid_argument("the points do not close around an axis");
    }
    // The unit curve's corners and its arcs between them in the spline space, each arc's ends
    // its corners to the last bit, so neighbouring arcs and rings meet exactly.
    const auto unit = [&](double theta) {
        return (frame.e1 * std::cos(theta) + frame.e2 * std::sin(theta)) * fit.c(theta);
    };
    std::vector<Vec3> corner(kRingSectors + 1);
    for (int i = 0; i < kRingSectors; ++i) {
        corner[i] = unit(kTwoPi * i / kRingSectors);
    }
    corner[kRingSectors] = corner[0];
    std::vector<std::vector<Vec3>> arcs;
    for (int i = 0; i < kRingSectors; ++i) {
        const double from = kTwoPi * i / kRingSectors;
        std::vector<Vec3> controls = fitControlPoints(
            space, [&](double t) { return unit(from + t * kTwoPi / kRingSectors); });
        controls.front() = corner[i];
        controls.back() = corner[i + 1];
        arcs.push_back(std::move(controls));
    }
    // Curve j: centre O_j plus ρ_j times the unit curve, so ring j (between curves j and j + 1)
    // is the general cone through both: its b is a scaled translate of its a.
    const auto centre = [&](int j) {
        return frame.origin + frame.axis * fit.heights[j] + frame.e1 * fit.cx[j] +
               frame.e2 * fit.cy[j];
    };
    CompositeSurface s;
    s.setName("rings");
    std::vector<std::vector<VertexId>> grid(count + 1, std::vector<VertexId>(kRingSectors));
    for (int j = 0; j <= count; ++j) {
        for (int i = 0; i < kRingSectors; ++i) {
            grid[j][i] = s.addVertex(centre(j) + corner[i] * fit.scale[j]);
        }
    }
    for (int j = 0; j < count; ++j) {
        for (int i = 0; i < kRingSectors; ++i) {
            const int next = (i + 1) % kRingSectors;
            s.addFace({grid[j][i], grid[j][next], grid[j + 1][next], grid[j + 1][i]});
        }
    }
    for (int j = 0; j <= count; ++j) {
        for (int i = 0; i < kRingSectors; ++i) {
            std::vector<Vec3> controls;
            for (const Vec3& c : arcs[i]) {
                controls.push_back(centre(j) + c * fit.scale[j]);
            }
            s.setSpline(grid[j][i], grid[j][(i + 1) % kRingSectors], space, controls);
        }
    }
    return s;
}

} // namespace devsurf::model::reference
