#include "quality_colours.h"

#include <vtkLookupTable.h>
#include <vtkRenderer.h>
#include <vtkScalarBarActor.h>
#include <vtkTextProperty.h>
#include <vtkUnsignedCharArray.h>

#include <QCoreApplication>

#include <algorithm>
#include <cmath>
#include <map>

namespace devsurf::views {

using model::Vec3;

namespace {

constexpr double kPi = 3.14159265358979323846;

// |det(m, da, db)| / (|m| |da| |db|) of the quad a0 a1 b1 b0 (a strip's sampled quad).
double quadDevelopability(const Vec3& a0, const Vec3& a1, const Vec3& b1, const Vec3& b0) {
    const Vec3 m = (a0 + a1) * 0.5 - (b0 + b1) * 0.5;
    const Vec3 da = a1 - a0;
    const Vec3 db = b1 - b0;
    const double scale = m.norm() * da.norm() * db.norm();
    return scale > 0.0 ? std::abs(dot(m, cross(da, db))) / scale : 0.0;
}

// δ: the distance of the two diagonals over the mean of the two shortest edges.
double quadFlatness(const Vec3& p0, const Vec3& p1, const Vec3& p2, const Vec3& p3) {
    const Vec3 u = p2 - p0;
    const Vec3 v = p3 - p1;
    const Vec3 n = cross(u, v);
    double distance = 0.0;
    if (n.norm() > 0.0) {
        distance = std::abs(dot(p1 - p0, n)) / n.norm();
    }
    double edges[4] = {(p1 - p0).norm(), (p2 - p1).norm(), (p3 - p2).norm(), (p0 - p3).norm()};
    std::sort(edges, edges + 4);
    const double mean = 0.5 * (edges[0] + edges[1]);
    return mean > 0.0 ? distance / mean : 0.0;
}

} // namespace

bool isPerPoint(ColourBy by) {
    return by == ColourBy::AngleDefect;
}

std::vector<double> qualityValues(const SurfaceScene& scene, ColourBy by) {
    std::vector<double> values;
    if (by == ColourBy::Developability || by == ColourBy::Flatness) {
        values.reserve(scene.polygons.size());
        for (const std::vector<int>& polygon : scene.polygons) {
            if (polygon.size() != 4) {
                values.push_back(0.0); // triangles of cones and fans are flat
                continue;
            }
            const Vec3& p0 = scene.points[static_cast<std::size_t>(polygon[0])];
            const Vec3& p1 = scene.points[static_cast<std::size_t>(polygon[1])];
            const Vec3& p2 = scene.points[static_cast<std::size_t>(polygon[2])];
            const Vec3& p3 = scene.points[static_cast<std::size_t>(polygon[3])];
            values.push_back(by == ColourBy::Developability ? quadDevelopability(p0, p1, p2, p3)
                                                            : quadFlatness(p0, p1, p2, p3));
        }
    } else if (by == ColourBy::AngleDefect && scene.pointOrigin.size() == scene.points.size()) {
        // Angle sums per sampled-mesh vertex; a vertex on an edge used by one polygon only is
        // on the boundary and has no defect.
        std::map<int, double> sums;
        std::map<std::pair<int, int>, int> edgeUses;
        for (const std::vector<int>& polygon : scene.polygons) {
            const std::size_t n = polygon.size();
            for (std::size_t i = 0; i < n; ++i) {
                const auto at = [&](std::size_t k) {
                    return scene.points[static_cast<std::size_t>(polygon[k % n])];
                };
                const Vec3 e1 = at(i + 1) - at(i);
                const Vec3 e2 = at(i + n - 1) - at(i);
                const double denominator = e1.norm() * e2.norm();
                const int origin = scene.pointOrigin[static_cast<std::size_t>(polygon[i])];
                if (denominator > 0.0) {
                    sums[origin] += std::acos(std::clamp(dot(e1, e2) / denominator, -1.0, 1.0));
                }
                const int next = scene.pointOrigin[static_cast<std::size_t>(polygon[(i + 1) % n])];
                ++edgeUses[std::minmax(origin, next)];
            }
        }
        std::map<int, bool> boundary;
        for (const auto& [edge, uses] : edgeUses) {
            if (uses == 1) {
                boundary[edge.first] = true;
                boundary[edge.second] = true;
            }
        }
        values.reserve(scene.points.size());
        for (int origin : scene.pointOrigin) {
            values.push_back(boundary.count(origin) != 0 ? 0.0
                                                         : std::abs(2.0 * kPi - sums[origin]));
        }
    }
    return values;
}

QualityColouring::QualityColouring(vtkRenderer* renderer)
    : m_table(vtkSmartPointer<vtkLookupTable>::New()),
      m_bar(vtkSmartPointer<vtkScalarBarActor>::New()) {
    m_table->SetScaleToLog10();
    // Blue (good) through green and yellow to red (far from the goal).
    m_table->SetHueRange(0.66, 0.0);
    m_table->SetNumberOfTableValues(256);
    m_table->Build();
    m_bar->SetLookupTable(m_table);
    m_bar->SetNumberOfLabels(5);
    m_bar->SetLabelFormat("%.0e");
    m_bar->SetPosition(0.88, 0.25);
    m_bar->SetWidth(0.1);
    m_bar->SetHeight(0.6);
    m_bar->UnconstrainedFontSizeOn();
    for (vtkTextProperty* text : {m_bar->GetTitleTextProperty(), m_bar->GetLabelTextProperty()}) {
        text->SetColor(0.1, 0.1, 0.1);
        text->ShadowOff();
        text->ItalicOff();
        text->BoldOff();
        text->SetFontSize(12);
    }
    m_bar->SetVisibility(false);
    renderer->AddActor2D(m_bar);
}

QualityColouring::~QualityColouring() = default;

void QualityColouring::setMode(ColourBy by) {
    m_mode = by;
    m_bar->SetVisibility(by != ColourBy::Patch);
    m_bar->SetTitle(title().toUtf8().constData());
}

QString QualityColouring::title() const {
    switch (m_mode) {
    case ColourBy::Developability:
        return QCoreApplication::translate("SceneView",
                                           "Developability\n|det(a-b, a', b')|\n(ratio)");
    case ColourBy::Flatness:
        return QCoreApplication::translate("SceneView", "Flatness δ\n(ratio)");
    case ColourBy::AngleDefect:
        return QCoreApplication::translate("SceneView", "Angle defect |K|\n(rad)");
    case ColourBy::Patch:
        break;
    }
    return QString();
}

void QualityColouring::update(const std::vector<SurfaceScene>& scenes) {
    m_values.clear();
    if (m_mode == ColourBy::Patch) {
        return;
    }
    for (const SurfaceScene& scene : scenes) {
        const std::vector<double> values = qualityValues(scene, m_mode);
        m_values.insert(m_values.end(), values.begin(), values.end());
    }
    double high = 0.0;
    for (double v : m_values) {
        high = std::max(high, std::isfinite(v) ? v : 0.0);
    }
    // Ten decades below the worst value, and never below 1e-12: exact zeros (cones, flat
    // designs) sit at the bottom of the scale.
    m_high = std::max(high, 1e-10);
    m_low = std::max(m_high * 1e-10, 1e-12);
    m_table->SetTableRange(m_low, m_high);
    m_table->Build();
}

std::array<double, 3> QualityColouring::colour(double value) const {
    double rgb[3];
    m_table->GetColor(std::clamp(std::isfinite(value) ? value : m_high, m_low, m_high), rgb);
    return {rgb[0], rgb[1], rgb[2]};
}

vtkSmartPointer<vtkUnsignedCharArray> QualityColouring::pointColours() const {
    auto colours = vtkSmartPointer<vtkUnsignedCharArray>::New();
    colours->SetNumberOfComponents(3);
    colours->SetName("quality");
    colours->SetNumberOfTuples(static_cast<vtkIdType>(m_values.size()));
    for (std::size_t i = 0; i < m_values.size(); ++i) {
        const std::array<double, 3> rgb = colour(m_values[i]);
        unsigned char value[3];
        for (int k = 0; k < 3; ++k) {
            value[k] =
                static_cast<unsigned char>(std::lround(255.0 * rgb[static_cast<std::size_t>(k)]));
        }
        colours->SetTypedTuple(static_cast<vtkIdType>(i), value);
    }
    return colours;
}

} // namespace devsurf::views
