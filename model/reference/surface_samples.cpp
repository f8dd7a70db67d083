#include "surface_samples.h"

#include "model/model_error.h"

#include <algorithm>
#include <cmath>

namespace devsurf::model::reference {

namespace {

constexpr int kMaxRulingSteps = 1000;

// The number of non-empty knot spans of a curve over its domain.
int intervalCount(const BSplineCurve& curve) {
    if (curve.isEmpty()) {
        return 0;
    }
    std::vector<double> breaks;
    for (double t : curve.knots()) {
        if (t >= curve.domainBegin() && t <= curve.domainEnd() &&
            (breaks.empty() || t > breaks.back())) {
            breaks.push_back(t);
        }
    }
    return std::max(1, static_cast<int>(breaks.size()) - 1);
}

double triangleArea(const Vec3& a, const Vec3& b, const Vec3& c) {
    return 0.5 * cross(b - a, c - a).norm();
}

// A strip's grid: u steps, ruling steps, and the length of its longest u step.
struct StripGrid {
    int uSteps = 1;
    int vSteps = 1;
    double uSpacing = 0.0;
};

StripGrid gridOf(const Strip& strip, int samplesPerInterval) {
    StripGrid grid;
    grid.uSteps = std::max(intervalCount(strip.a), intervalCount(strip.b)) * samplesPerInterval;
    double longestRuling = 0.0;
    for (int i = 0; i <= grid.uSteps; ++i) {
        const double u = static_cast<double>(i) / grid.uSteps;
        longestRuling = std::max(longestRuling, distance(strip.aPoint(u), strip.bPoint(u)));
        if (i > 0) {
            const double w = static_cast<double>(i - 1) / grid.uSteps;
            grid.uSpacing = std::max({grid.uSpacing, distance(strip.aPoint(u), strip.aPoint(w)),
                                      distance(strip.bPoint(u), strip.bPoint(w))});
        }
    }
    const double steps = grid.uSpacing > 0.0 ? std::ceil(longestRuling / grid.uSpacing) : 1.0;
    grid.vSteps = static_cast<int>(std::clamp(steps, 1.0, double(kMaxRulingSteps)));
    return grid;
}

class Sampler {
public:
    explicit Sampler(SurfaceSamples& out) : m_out(out) {}

    void addStrip(const StripGrid& grid) {
        const auto pieceIndex = static_cast<std::uint32_t>(m_out.pieces.size() - 1);
        const Strip& strip = m_out.pieces.back().strip;
        const std::size_t first = m_out.positions.size();
        const int columns = grid.vSteps + 1;
        for (int i = 0; i <= grid.uSteps; ++i) {
            const double u = static_cast<double>(i) / grid.uSteps;
            const Vec3 a = strip.aPoint(u);
            const Vec3 b = strip.bPoint(u);
            for (int j = 0; j <= grid.vSteps; ++j) {
                const double v = static_cast<double>(j) / grid.vSteps;
                add(a * (1.0 - v) + b * v, pieceIndex, u, v);
            }
        }
        // Each cell's area (from its diagonals) a quarter to each corner; its diameter bounds
        // how far a point of the cell can be from the nearest corner.
        for (int i = 0; i < grid.uSteps; ++i) {
            for (int j = 0; j < grid.vSteps; ++j) {
                const std::size_t corner[4] = {
                    first + static_cast<std::size_t>(i * columns + j),
                    first + static_cast<std::size_t>((i + 1) * columns + j),
                    first + static_cast<std::size_t>((i + 1) * columns + j + 1),
                    first + static_cast<std::size_t>(i * columns + j + 1)};
                const Vec3* p[4];
                for (int k = 0; k < 4; ++k) {
                    p[k] = &m_out.positions[corner[k]];
                }
                const double cellArea = 0.5 * cross(*p[2] - *p[0], *p[3] - *p[1]).norm();
                for (std::size_t c : corner) {
                    m_out.area[c] += 0.25 * cellArea;
                }
                for (int k = 0; k < 4; ++k) {
                    for (int l = k + 1; l < 4; ++l) {
                        cover(distance(*p[k], *p[l]));
                    }
                }
            }
        }
    }

    // A triangle of a planar face on a grid of `steps` steps per side.
    void addTriangle(int steps) {
        const auto pieceIndex = static_cast<std::uint32_t>(m_out.pieces.size() - 1);
        const Vec3* t = m_out.pieces.back().triangle;
        const std::size_t first = m_out.positions.size();
        auto indexOf = [first, steps](int i, int j) {
            // Row i holds steps + 1 − i points.
            return first + static_cast<std::size_t>(i * (steps + 1) - i * (i - 1) / 2 + j);
        };
        for (int i = 0; i <= steps; ++i) {
            for (int j = 0; i + j <= steps; ++j) {
                const Vec3 p = t[0] + (t[1] - t[0]) * (static_cast<double>(i) / steps) +
                               (t[2] - t[0]) * (static_cast<double>(j) / steps);
                add(p, pieceIndex, 0.0, 0.0);
            }
        }
        const double share = triangleArea(t[0], t[1], t[2]) / (3.0 * steps * steps);
        for (int i = 0; i < steps; ++i) {
            for (int j = 0; i + j < steps; ++j) {
                for (std::size_t c : {indexOf(i, j), indexOf(i + 1, j), indexOf(i, j + 1)}) {
                    m_out.area[c] += share;
                }
                if (i + j + 1 < steps) {
                    for (std::size_t c :
                         {indexOf(i + 1, j), indexOf(i + 1, j + 1), indexOf(i, j + 1)}) {
                        m_out.area[c] += share;
                    }
                }
            }
        }
        cover(std::max({distance(t[0], t[1]), distance(t[1], t[2]), distance(t[2], t[0])}) / steps);
    }

private:
    void add(const Vec3& p, std::uint32_t pieceIndex, double u, double v) {
        m_out.positions.push_back(p);
        m_out.piece.push_back(pieceIndex);
        m_out.u.push_back(u);
        m_out.v.push_back(v);
        m_out.area.push_back(0.0);
    }
    void cover(double diameter) { m_out.coveringRadius = std::max(m_out.coveringRadius, diameter); }

    SurfaceSamples& m_out;
};

} // namespace

SurfaceSamples sampleDensely(const std::vector<CompositeSurface>& surfaces,
                             int samplesPerInterval) {
    if (samplesPerInterval < 1 || samplesPerInterval > 1000) {
        Problem problem = problemOf(ProblemCode::SampleCount);
        problem.count = samplesPerInterval;
        problem.expected = 1000;
        throw ModelError(problem);
    }
    for (const CompositeSurface& surface : surfaces) {
        const auto problems = surface.validate();
        if (!problems.empty()) {
            throw ModelError(problems.front());
        }
    }
    SurfaceSamples out;
    Sampler sampler(out);
    // Strips first: their u spacing sets the spacing of the planar faces' grids.
    double spacing = 0.0;
    for (std::size_t s = 0; s < surfaces.size(); ++s) {
        for (Strip& strip : stripsOf(surfaces[s])) {
            const StripGrid grid = gridOf(strip, samplesPerInterval);
            spacing = std::max(spacing, grid.uSpacing);
            SurfacePiece piece;
            piece.surface = s;
            piece.face = strip.face;
            piece.isStrip = true;
            piece.strip = std::move(strip);
            out.pieces.push_back(std::move(piece));
            sampler.addStrip(grid);
        }
    }
    std::vector<SurfacePiece> triangles;
    double longestSide = 0.0;
    for (std::size_t s = 0; s < surfaces.size(); ++s) {
        for (const auto& [face, loop] : surfaces[s].faces()) {
            if (surfaces[s].faceType(face) != FaceType::Planar) {
                continue;
            }
            for (std::size_t i = 1; i + 1 < loop.size(); ++i) {
                SurfacePiece piece;
                piece.surface = s;
                piece.face = face;
                piece.triangle[0] = surfaces[s].position(loop[0]);
                piece.triangle[1] = surfaces[s].position(loop[i]);
                piece.triangle[2] = surfaces[s].position(loop[i + 1]);
                for (int k = 0; k < 3; ++k) {
                    longestSide = std::max(
                        longestSide, distance(piece.triangle[k], piece.triangle[(k + 1) % 3]));
                }
                triangles.push_back(std::move(piece));
            }
        }
    }
    if (!(spacing > 0.0)) { // planar faces only
        spacing = longestSide / samplesPerInterval;
    }
    for (SurfacePiece& piece : triangles) {
        double side = 0.0;
        for (int k = 0; k < 3; ++k) {
            side = std::max(side, distance(piece.triangle[k], piece.triangle[(k + 1) % 3]));
        }
        const double steps = spacing > 0.0 ? std::ceil(side / spacing) : 1.0;
        out.pieces.push_back(std::move(piece));
        sampler.addTriangle(static_cast<int>(std::clamp(steps, 1.0, double(kMaxRulingSteps))));
    }
    return out;
}

} // namespace devsurf::model::reference
