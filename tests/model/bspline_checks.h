#pragma once

// The B-spline tests' curves and checks (tst_bspline.cpp): a sweep of uniform spaces, open and
// closed, and the checks each curve gets — evaluation against an independent Cox–de Boor
// reference, derivatives, smoothness and the editing operations keeping the geometry. A check
// records failures with QVERIFY; RUN_CHECK returns from the calling test once one failed.

#include "bspline_curve.h"

#include <QByteArray>
#include <QTest>

#include <random>
#include <utility>
#include <vector>

// Returns from the calling test function when a helper has recorded a failure.
#define RUN_CHECK(call)                                                                            \
    do {                                                                                           \
        call;                                                                                      \
        if (QTest::currentTestFailed())                                                            \
            return;                                                                                \
    } while (false)

namespace devsurf::test::bspline {

using model::BSplineCurve;
using model::Vec3;

struct Case {
    BSplineCurve curve;
    QByteArray name;
    int degree = 0;
    int smoothness = 0;
    int intervals = 0;
    bool closed = false;
    double diameter = 0.0; // of the control polygon; the geometric scale
};

std::vector<Vec3> randomPoints(std::mt19937& rng, int count, double scale);
// The larger of the points' bounding-box diagonal and their largest coordinate.
double diameterOf(const std::vector<Vec3>& points);
// Every uniform space with degree 1..5, every smoothness, several interval counts, open and
// closed. geometryScale scales the control points, parameterScale the parameter domain
// (those curves go through the general constructor).
std::vector<Case> sweep(double geometryScale = 1.0, double parameterScale = 1.0,
                        unsigned seed = 12345);
std::vector<double> distinctDomainKnots(const BSplineCurve& curve);
// Parameters including every knot, both ends and random values.
std::vector<double> sampleParameters(const BSplineCurve& curve, std::mt19937& rng,
                                     int randomCount = 25);
// The non-empty spans of the domain.
std::vector<std::pair<double, double>> spans(const BSplineCurve& curve);
double maxDeviation(const BSplineCurve& a, const BSplineCurve& b,
                    const std::vector<double>& parameters);
std::vector<double> uniformSamples(double begin, double end, int count);
QByteArray describe(const Case& c, double u);
// Independent reference: Σ P_{i mod N} N_i(u) by the Cox–de Boor recursion.
Vec3 coxDeBoor(int m, const std::vector<double>& knots, const std::vector<Vec3>& points, double u);
// Periodic knot sequence t_0..t_{N+2m} from the knots of one period.
std::vector<double> periodicKnots(int m, const std::vector<double>& base, double period);

void checkRows(const Case& c, std::mt19937& rng);
void checkDerivatives(const Case& c);
void checkSmoothness(const Case& c);
void checkSameGeometry(const Case& c, const BSplineCurve& changed, const QByteArray& what);
void checkPeriodicRepresentation(const BSplineCurve& curve, const QByteArray& what);
void checkInsertion(const Case& c, std::mt19937& rng);
void checkSplit(const Case& c, std::mt19937& rng);
void checkOpenedAt(const Case& c, std::mt19937& rng);
void checkReversed(const Case& c);

} // namespace devsurf::test::bspline
