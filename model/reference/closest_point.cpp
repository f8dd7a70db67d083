#include "closest_point.h"

#include <algorithm>
#include <cmath>

namespace devsurf::model::reference {

namespace {

constexpr int kMaxNewtonSteps = 60;
// A step is over when it moves the parameters less than this (they live in [0,1]).
constexpr double kParameterStep = 1e-15;
constexpr double kSmallestLineStep = 1e-12;

// s and its partial derivatives at (u,v); s_vv = 0 because s is linear in v.
struct StripJet {
    Vec3 s, su, sv, suu, suv;
};

StripJet jetAt(const Strip& strip, double u, double v) {
    const DeBoorPoints a = strip.a.deBoorPoints(u);
    Vec3 b = strip.apex;
    Vec3 bu;
    Vec3 buu;
    if (!strip.isCone()) {
        const DeBoorPoints bPoints = strip.b.deBoorPoints(u);
        b = bPoints.point;
        bu = bPoints.firstDerivative();
        buu = bPoints.secondDerivative();
    }
    const Vec3 au = a.firstDerivative();
    const Vec3 auu = a.secondDerivative();
    StripJet jet;
    jet.s = a.point * (1.0 - v) + b * v;
    jet.su = au * (1.0 - v) + bu * v;
    jet.sv = b - a.point;
    jet.suu = auu * (1.0 - v) + buu * v;
    jet.suv = bu - au;
    return jet;
}

Vec3 closestOnSegment(const Vec3& a, const Vec3& b, const Vec3& q) {
    const Vec3 ab = b - a;
    const double length = ab.squaredNorm();
    const double t = length > 0.0 ? std::clamp(dot(q - a, ab) / length, 0.0, 1.0) : 0.0;
    return a + ab * t;
}

double squaredGap(const Strip& strip, const Vec3& q, double u, double v) {
    return (strip.point(u, v) - q).squaredNorm();
}

// One projected Newton direction for f = ½|s − q|² at (u,v) with gradient g: parameters held on
// the border of [0,1]² where g pushes them out stay; the others take the Newton step of their
// block of the Hessian, or of the Gauss–Newton matrix JᵀJ where that block is not positive
// definite.
void newtonDirection(const StripJet& jet, const Vec3& r, const double x[2], const double g[2],
                     double d[2]) {
    const double gauss[3] = {dot(jet.su, jet.su), dot(jet.su, jet.sv), dot(jet.sv, jet.sv)};
    const double hessian[3] = {gauss[0] + dot(r, jet.suu), gauss[1] + dot(r, jet.suv), gauss[2]};
    bool free[2];
    for (int k = 0; k < 2; ++k) {
        free[k] = !((x[k] <= 0.0 && g[k] > 0.0) || (x[k] >= 1.0 && g[k] < 0.0));
    }
    d[0] = d[1] = 0.0;
    if (free[0] && free[1]) {
        for (const double* h : {hessian, gauss}) {
            const double det = h[0] * h[2] - h[1] * h[1];
            if (h[0] > 0.0 && det > 1e-14 * h[0] * h[2]) {
                d[0] = -(h[2] * g[0] - h[1] * g[1]) / det;
                d[1] = -(h[0] * g[1] - h[1] * g[0]) / det;
                return;
            }
        }
        // Rank-deficient (a ruling of zero length, the apex): move along one parameter.
        free[g[0] * g[0] * gauss[2] >= g[1] * g[1] * gauss[0] ? 1 : 0] = false;
    }
    for (int k = 0; k < 2; ++k) {
        if (!free[k]) {
            continue;
        }
        const double diagonal = k == 0 ? hessian[0] : hessian[2];
        const double fallback = k == 0 ? gauss[0] : gauss[2];
        const double h = diagonal > 0.0 ? diagonal : fallback;
        if (h > 0.0) {
            d[k] = -g[k] / h;
        }
    }
}

} // namespace

ClosestPoint closestPointOnStrip(const Strip& strip, const Vec3& q, double u0, double v0) {
    double x[2] = {std::clamp(u0, 0.0, 1.0), std::clamp(v0, 0.0, 1.0)};
    double f = squaredGap(strip, q, x[0], x[1]);
    for (int step = 0; step < kMaxNewtonSteps; ++step) {
        const StripJet jet = jetAt(strip, x[0], x[1]);
        const Vec3 r = jet.s - q;
        const double g[2] = {dot(r, jet.su), dot(r, jet.sv)};
        double d[2];
        newtonDirection(jet, r, x, g, d);
        if (d[0] == 0.0 && d[1] == 0.0) {
            break;
        }
        // Backtrack until the (clamped) step does not increase the distance.
        double t = 1.0;
        double next[2] = {x[0], x[1]};
        double fNext = f;
        bool accepted = false;
        for (; t >= kSmallestLineStep; t *= 0.5) {
            next[0] = std::clamp(x[0] + t * d[0], 0.0, 1.0);
            next[1] = std::clamp(x[1] + t * d[1], 0.0, 1.0);
            fNext = squaredGap(strip, q, next[0], next[1]);
            if (fNext <= f) {
                accepted = true;
                break;
            }
        }
        if (!accepted) {
            break;
        }
        const double moved = std::max(std::abs(next[0] - x[0]), std::abs(next[1] - x[1]));
        x[0] = next[0];
        x[1] = next[1];
        f = fNext;
        if (moved < kParameterStep) {
            break;
        }
    }
    ClosestPoint result;
    result.u = x[0];
    result.v = x[1];
    result.position = strip.point(x[0], x[1]);
    result.distance = distance(result.position, q);
    return result;
}

ClosestPoint closestPointOnTriangle(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& q) {
    // The Voronoi regions of the corners, then of the edges, else the inside (barycentric).
    const Vec3 ab = b - a;
    const Vec3 ac = c - a;
    const Vec3 aq = q - a;
    auto done = [&q](const Vec3& p) {
        ClosestPoint result;
        result.position = p;
        result.distance = distance(p, q);
        return result;
    };
    const double d1 = dot(ab, aq);
    const double d2 = dot(ac, aq);
    if (d1 <= 0.0 && d2 <= 0.0) {
        return done(a);
    }
    const Vec3 bq = q - b;
    const double d3 = dot(ab, bq);
    const double d4 = dot(ac, bq);
    if (d3 >= 0.0 && d4 <= d3) {
        return done(b);
    }
    const double vc = d1 * d4 - d3 * d2;
    if (vc <= 0.0 && d1 >= 0.0 && d3 <= 0.0) {
        return done(a + ab * (d1 / (d1 - d3)));
    }
    const Vec3 cq = q - c;
    const double d5 = dot(ab, cq);
    const double d6 = dot(ac, cq);
    if (d6 >= 0.0 && d5 <= d6) {
        return done(c);
    }
    const double vb = d5 * d2 - d1 * d6;
    if (vb <= 0.0 && d2 >= 0.0 && d6 <= 0.0) {
        return done(a + ac * (d2 / (d2 - d6)));
    }
    const double va = d3 * d6 - d5 * d4;
    if (va <= 0.0 && (d4 - d3) >= 0.0 && (d5 - d6) >= 0.0) {
        return done(b + (c - b) * ((d4 - d3) / ((d4 - d3) + (d5 - d6))));
    }
    const double sum = va + vb + vc;
    if (!(sum > 0.0)) { // a degenerate triangle: the nearest of its three sides
        ClosestPoint best = done(closestOnSegment(a, b, q));
        for (const ClosestPoint& side :
             {done(closestOnSegment(b, c, q)), done(closestOnSegment(c, a, q))}) {
            best = side.distance < best.distance ? side : best;
        }
        return best;
    }
    return done(a + ab * (vb / sum) + ac * (vc / sum));
}

} // namespace devsurf::model::reference
