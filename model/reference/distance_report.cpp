#include "distance_report.h"

#include "bounding_box.h"
#include "closest_point.h"
#include "point_index.h"
#include "surface_samples.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <numeric>
#include <stdexcept>
#include <thread>

namespace devsurf::model::reference {

namespace {

ClosestPoint closestOnPiece(const SurfaceSamples& samples, std::size_t sample, const Vec3& q) {
    const SurfacePiece& piece = samples.pieces[samples.piece[sample]];
    if (piece.isStrip) {
        return closestPointOnStrip(piece.strip, q, samples.u[sample], samples.v[sample]);
    }
    return closestPointOnTriangle(piece.triangle[0], piece.triangle[1], piece.triangle[2], q);
}

// The distance from q to the sampled surface. A piece can hold a point closer than the best
// found so far only if one of its samples lies within best + coveringRadius of q; those pieces
// are refined from their nearest sample, nearest first.
double distanceToSurface(const SurfaceSamples& samples, const PointIndex& index, const Vec3& q,
                         std::vector<PointIndex::Neighbour>& ball,
                         std::vector<std::uint32_t>& refined) {
    const PointIndex::Neighbour nearest = index.nearest(q);
    double best = closestOnPiece(samples, nearest.index, q).distance;
    best = std::min(best, std::sqrt(nearest.squaredDistance));
    index.withinRadius(q, best + samples.coveringRadius, ball);
    refined.assign(1, samples.piece[nearest.index]);
    for (const auto& n : ball) {
        if (std::sqrt(n.squaredDistance) >= best + samples.coveringRadius) {
            break;
        }
        const std::uint32_t piece = samples.piece[n.index];
        if (std::find(refined.begin(), refined.end(), piece) != refined.end()) {
            continue;
        }
        refined.push_back(piece);
        best = std::min(best, closestOnPiece(samples, n.index, q).distance);
    }
    return best;
}

// Runs work(begin, end) over [0, count) split into one contiguous range per hardware thread.
// The queries only read shared data and write their own slots, so the result does not depend on
// the number of threads.
template <class Work> void inParallel(std::size_t count, const Work& work) {
    constexpr std::size_t kMinimumPerThread = 1024;
    const std::size_t threads = std::clamp<std::size_t>(
        std::min<std::size_t>(std::thread::hardware_concurrency(), count / kMinimumPerThread), 1,
        64);
    std::vector<std::thread> pool;
    for (std::size_t t = 1; t < threads; ++t) {
        pool.emplace_back(work, count * t / threads, count * (t + 1) / threads);
    }
    work(std::size_t{0}, count / threads);
    for (std::thread& thread : pool) {
        thread.join();
    }
}

// Mean, 95th percentile and max of values with weights (all 1 when `weights` is empty).
OneSidedDistance summarise(const std::vector<double>& values, const std::vector<double>& weights,
                           double diagonal) {
    OneSidedDistance d;
    if (values.empty()) {
        return d;
    }
    std::vector<std::size_t> order(values.size());
    std::iota(order.begin(), order.end(), std::size_t{0});
    std::sort(order.begin(), order.end(),
              [&values](std::size_t x, std::size_t y) { return values[x] < values[y]; });
    auto weight = [&weights](std::size_t i) { return weights.empty() ? 1.0 : weights[i]; };
    double total = 0.0;
    double weighted = 0.0;
    for (std::size_t i : order) {
        total += weight(i);
        weighted += weight(i) * values[i];
    }
    d.max = values[order.back()];
    d.mean = total > 0.0 ? weighted / total : 0.0;
    d.percentile95 = d.max;
    double below = 0.0;
    for (std::size_t i : order) {
        below += weight(i);
        if (below >= 0.95 * total) {
            d.percentile95 = values[i];
            break;
        }
    }
    if (diagonal > 0.0) {
        d.meanPercent = 100.0 * d.mean / diagonal;
        d.percentile95Percent = 100.0 * d.percentile95 / diagonal;
        d.maxPercent = 100.0 * d.max / diagonal;
    }
    return d;
}

// The distance from q to a mesh: the nearest of its kMeshNeighbours nearest vertices and of
// the triangles around them.
double distanceToMesh(const std::vector<Vec3>& points,
                      const std::vector<std::array<int, 3>>& triangles,
                      const std::vector<std::vector<std::uint32_t>>& around,
                      const PointIndex& index, const Vec3& q) {
    double best = std::numeric_limits<double>::max();
    for (const PointIndex::Neighbour& n : index.nearest(q, kMeshNeighbours)) {
        best = std::min(best, std::sqrt(n.squaredDistance));
        for (const std::uint32_t t : around[n.index]) {
            const std::array<int, 3>& c = triangles[t];
            best = std::min(best, closestPointOnTriangle(points[static_cast<std::size_t>(c[0])],
                                                         points[static_cast<std::size_t>(c[1])],
                                                         points[static_cast<std::size_t>(c[2])], q)
                                      .distance);
        }
    }
    return best;
}

} // namespace

DistanceReport measureDistance(const std::vector<CompositeSurface>& surfaces,
                               const std::vector<Vec3>& target, const DistanceOptions& options) {
    if (target.empty()) {
        throw std::invalid_argument("measureDistance: the target has no points");
    }
    if (!std::all_of(target.begin(), target.end(), [](const Vec3& p) { return p.isFinite(); })) {
        throw std::invalid_argument("measureDistance: the target has non-finite points");
    }
    // Cancelled: checked every kCancelStride points in the loops below, thrown after them.
    constexpr std::size_t kCancelStride = 256;
    auto cancelled = [&options] {
        return options.cancel != nullptr && options.cancel->load(std::memory_order_relaxed);
    };
    auto stopIfCancelled = [&cancelled] {
        if (cancelled()) {
            throw DistanceCancelled();
        }
    };
    // Per target point, the triangles around it (a mesh's surface → target).
    std::vector<std::vector<std::uint32_t>> around;
    if (options.triangles != nullptr && !options.triangles->empty()) {
        around.resize(target.size());
        for (std::size_t t = 0; t < options.triangles->size(); ++t) {
            for (const int corner : (*options.triangles)[t]) {
                if (corner < 0 || static_cast<std::size_t>(corner) >= target.size()) {
                    throw std::invalid_argument(
                        "measureDistance: a triangle's corner is not a target point");
                }
                around[static_cast<std::size_t>(corner)].push_back(static_cast<std::uint32_t>(t));
            }
        }
    }
    stopIfCancelled();
    SurfaceSamples samples = sampleDensely(surfaces, options.samplesPerInterval);
    if (samples.positions.empty()) {
        throw std::invalid_argument("measureDistance: the design has no faces");
    }
    DistanceReport report;
    report.diagonal = boundingBoxDiagonal(target);
    report.tolerance = options.tolerance > 0.0 ? options.tolerance : 0.01 * report.diagonal;
    report.surfaceSamples = samples.positions.size();
    report.surfaceSpacing = samples.coveringRadius;
    report.toMesh = !around.empty();

    const PointIndex surfaceIndex(std::move(samples.positions));
    report.targetDistances.resize(target.size());
    inParallel(target.size(), [&](std::size_t begin, std::size_t end) {
        std::vector<PointIndex::Neighbour> ball;
        std::vector<std::uint32_t> refined;
        for (std::size_t i = begin; i < end; ++i) {
            if ((i - begin) % kCancelStride == 0 && cancelled()) {
                return;
            }
            report.targetDistances[i] =
                distanceToSurface(samples, surfaceIndex, target[i], ball, refined);
        }
    });
    stopIfCancelled();
    const auto covered = std::count_if(report.targetDistances.begin(), report.targetDistances.end(),
                                       [&report](double d) { return d <= report.tolerance; });
    report.coverage = static_cast<double>(covered) / static_cast<double>(target.size());
    report.targetToSurface = summarise(report.targetDistances, {}, report.diagonal);

    const PointIndex targetIndex(target);
    const std::vector<Vec3>& onSurface = surfaceIndex.points();
    std::vector<double> toTarget(onSurface.size());
    inParallel(onSurface.size(), [&](std::size_t begin, std::size_t end) {
        for (std::size_t i = begin; i < end; ++i) {
            if ((i - begin) % kCancelStride == 0 && cancelled()) {
                return;
            }
            toTarget[i] =
                around.empty()
                    ? std::sqrt(targetIndex.nearest(onSurface[i]).squaredDistance)
                    : distanceToMesh(target, *options.triangles, around, targetIndex, onSurface[i]);
        }
    });
    stopIfCancelled();
    report.surfaceToTarget = summarise(toTarget, samples.area, report.diagonal);
    return report;
}

DistanceReport measureDistance(const CompositeSurface& surface, const std::vector<Vec3>& target,
                               const DistanceOptions& options) {
    return measureDistance(std::vector<CompositeSurface>{surface}, target, options);
}

} // namespace devsurf::model::reference
