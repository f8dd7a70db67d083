#include "sheet_creases.h"

#include "composite_surface.h"
#include "development.h"
#include "plane_motion.h"
#include "sampled_mesh.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <optional>
#include <set>

namespace devsurf::model {

namespace {

Vec2 placed(const SheetDomain& domain, const Vec2& p) {
    const double c = std::cos(domain.angle);
    const double s = std::sin(domain.angle);
    return domain.centre + Vec2(c * p.x - s * p.y, s * p.x + c * p.y);
}

double distanceTo(const DomainLoop& loop, const Vec2& p) {
    return (footPoint(loop, p).point - p).norm();
}

} // namespace

std::vector<DomainLoop> creaseCurveLoops(const SheetDomain& domain) {
    std::vector<DomainLoop> loops;
    for (const SheetDomain::Curve& curve : domain.creaseCurves) {
        DomainLoop loop;
        loop.open = !curve.closed;
        loop.smooth = true;
        loop.outer = false;
        for (const Vec2& p : curve.points) {
            loop.polygon.push_back(placed(domain, p));
        }
        loops.push_back(std::move(loop));
    }
    return loops;
}

std::vector<OnCreaseCurve> creaseSamplesOnCurves(const SheetDomain& domain,
                                                 const SampledMesh& mesh) {
    std::vector<OnCreaseCurve> held;
    std::set<std::pair<int, int>> seen;
    for (const SampledMesh::Polyline& line : mesh.splineEdges) {
        const auto it = domain.creaseCurveOf.find(line.edge);
        if (it == domain.creaseCurveOf.end() || it->second < 0 ||
            static_cast<std::size_t>(it->second) >= domain.creaseCurves.size()) {
            continue;
        }
        for (int v : line.vertices) {
            if (seen.insert({v, it->second}).second) {
                held.push_back({v, it->second});
            }
        }
    }
    return held;
}

std::map<EdgeId, int> assignCreasesToCurves(const SheetDomain& domain,
                                            const CompositeSurface& surface,
                                            const SampledMesh& mesh,
                                            const std::vector<Vec2>& development) {
    std::map<EdgeId, int> assigned;
    const std::vector<DomainLoop> curves = creaseCurveLoops(domain);
    std::vector<const SampledMesh::Polyline*> creases;
    for (const SampledMesh::Polyline& line : mesh.splineEdges) {
        if (surface.hasEdge(line.edge) && surface.facesOfEdge(line.edge).size() == 2 &&
            line.vertices.size() >= 2) {
            creases.push_back(&line);
        }
    }
    auto at = [&development](int v) { return development[static_cast<std::size_t>(v)]; };
    for (const SampledMesh::Polyline* line : creases) {
        double length = 0.0;
        for (std::size_t i = 1; i < line->vertices.size(); ++i) {
            length += (at(line->vertices[i]) - at(line->vertices[i - 1])).norm();
        }
        int best = -1;
        double bestMean = std::numeric_limits<double>::infinity();
        for (std::size_t c = 0; c < curves.size(); ++c) {
            double sum = 0.0;
            for (int v : line->vertices) {
                sum += distanceTo(curves[c], at(v));
            }
            const double mean = sum / static_cast<double>(line->vertices.size());
            if (mean < bestMean) {
                bestMean = mean;
                best = static_cast<int>(c);
            }
        }
        if (best < 0 || bestMean > kCreaseCurveReach * length) {
            continue;
        }
        // The curve is this crease's where no other crease lies nearer it: for most samples,
        // the sample is the nearest of all creases' samples to its foot on the curve.
        const std::set<int> own(line->vertices.begin(), line->vertices.end());
        std::size_t nearest = 0;
        for (int v : line->vertices) {
            const Vec2 foot = footPoint(curves[static_cast<std::size_t>(best)], at(v)).point;
            const double mine = (at(v) - foot).norm();
            bool beaten = false;
            for (std::size_t k = 0; k < creases.size() && !beaten; ++k) {
                for (int w : creases[k]->vertices) {
                    if (own.count(w) == 0 && (at(w) - foot).norm() < mine) {
                        beaten = true;
                        break;
                    }
                }
            }
            nearest += beaten ? 0 : 1;
        }
        if (2 * nearest >= line->vertices.size()) {
            assigned[line->edge] = best;
        }
    }
    return assigned;
}

double largestCreaseCurveGap(const SheetDomain& domain, const SampledMesh& mesh,
                             const std::vector<Vec2>& development) {
    const std::vector<DomainLoop> curves = creaseCurveLoops(domain);
    double gap = 0.0;
    for (const OnCreaseCurve& on : creaseSamplesOnCurves(domain, mesh)) {
        if (static_cast<std::size_t>(on.vertex) < development.size()) {
            gap = std::max(gap, distanceTo(curves[static_cast<std::size_t>(on.curve)],
                                           development[static_cast<std::size_t>(on.vertex)]));
        }
    }
    return gap;
}

std::vector<SheetDomain::Curve> creaseCurvesAsTheyLie(const CompositeSurface& surface,
                                                      const std::vector<Vec2>& development) {
    if (!surface.validate().empty()) {
        return {};
    }
    const SampledMesh fine = sampleSurface(surface, kCreaseCurveSamples);
    const std::size_t coarse = fine.coarseVertexIds.size();
    if (development.size() < coarse || coarse < 2) {
        return {};
    }
    const Development unfolded = unfoldSampledMesh(fine);
    if (unfolded.components != 1 || unfolded.period) {
        return {};
    }
    const std::optional<PlaneMotion> onto = fitPlaneMotion(
        std::vector<Vec2>(unfolded.vertices.begin(),
                          unfolded.vertices.begin() + static_cast<long>(coarse)),
        std::vector<Vec2>(development.begin(), development.begin() + static_cast<long>(coarse)));
    if (!onto) {
        return {};
    }
    // The creases, and at every coarse vertex the creases that meet there.
    std::vector<const SampledMesh::Polyline*> creases;
    std::map<int, std::vector<std::size_t>> meeting; // mesh vertex -> indices into creases
    for (const SampledMesh::Polyline& line : fine.splineEdges) {
        if (surface.facesOfEdge(line.edge).size() == 2 && line.vertices.size() >= 2) {
            meeting[line.vertices.front()].push_back(creases.size());
            meeting[line.vertices.back()].push_back(creases.size());
            creases.push_back(&line);
        }
    }
    // The crease continuing `k` through vertex `v`, if exactly two meet there.
    auto across = [&](std::size_t k, int v) -> std::optional<std::size_t> {
        const std::vector<std::size_t>& here = meeting[v];
        if (here.size() != 2 || here[0] == here[1]) {
            return std::nullopt;
        }
        return here[0] == k ? here[1] : here[0];
    };
    auto ends = [&](std::size_t k) {
        return std::pair(creases[k]->vertices.front(), creases[k]->vertices.back());
    };
    std::vector<bool> used(creases.size(), false);
    std::vector<SheetDomain::Curve> curves;
    for (std::size_t first = 0; first < creases.size(); ++first) {
        if (used[first]) {
            continue;
        }
        // Back up to where the chain starts (or all the way round a closed one).
        std::size_t k = first;
        int start = ends(first).first;
        for (std::size_t guard = 0; guard < creases.size(); ++guard) {
            const auto previous = across(k, start);
            if (!previous || *previous == first) {
                break;
            }
            k = *previous;
            start = ends(k).first == start ? ends(k).second : ends(k).first;
        }
        // Walk forwards from there, each crease's samples in the direction of travel.
        std::vector<int> chain{start};
        int at = start;
        while (!used[k]) {
            used[k] = true;
            std::vector<int> samples = creases[k]->vertices;
            if (samples.front() != at) {
                std::reverse(samples.begin(), samples.end());
            }
            chain.insert(chain.end(), samples.begin() + 1, samples.end());
            at = samples.back();
            const auto next = across(k, at);
            if (!next) {
                break;
            }
            k = *next;
        }
        SheetDomain::Curve curve;
        curve.closed = chain.size() > 3 && chain.back() == chain.front();
        if (curve.closed) {
            chain.pop_back();
        }
        for (int v : chain) {
            curve.points.push_back(onto->apply(unfolded.vertices[static_cast<std::size_t>(v)]));
        }
        curves.push_back(std::move(curve));
    }
    return curves;
}

std::vector<SheetDomain::Curve> sheetFrameCurves(const SheetDomain& domain,
                                                 std::vector<SheetDomain::Curve> curves) {
    const double c = std::cos(-domain.angle);
    const double s = std::sin(-domain.angle);
    for (SheetDomain::Curve& curve : curves) {
        for (Vec2& p : curve.points) {
            const Vec2 d = p - domain.centre;
            p = Vec2(c * d.x - s * d.y, s * d.x + c * d.y);
        }
    }
    return curves;
}

std::vector<SheetDomain::Curve> sheetCurvesFromAbove(const std::vector<ReferenceCurve>& curves,
                                                     const Vec2& shift) {
    std::vector<SheetDomain::Curve> result;
    for (const ReferenceCurve& curve : curves) {
        const std::vector<Vec3>& p = curve.points;
        if (p.size() < 2) {
            continue;
        }
        double length = 0.0;
        for (std::size_t i = 1; i < p.size(); ++i) {
            length += distance(p[i - 1], p[i]);
        }
        SheetDomain::Curve out;
        out.closed = p.size() >= 4 && distance(p.front(), p.back()) <= 1e-6 * length;
        const std::size_t count = out.closed ? p.size() - 1 : p.size();
        for (std::size_t i = 0; i < count; ++i) {
            out.points.emplace_back(p[i].x + shift.x, p[i].y + shift.y);
        }
        result.push_back(std::move(out));
    }
    return result;
}

} // namespace devsurf::model
