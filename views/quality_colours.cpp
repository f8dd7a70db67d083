#include "quality_colours.h"

#include "solver/core/options.h"

#include <vtkLookupTable.h>
#include <vtkUnsignedCharArray.h>

#include <QColor>
#include <QCoreApplication>

#include <algorithm>
#include <cmath>
#include <limits>

namespace devsurf::views {

bool isPerPoint(ColourBy by) {
    return by == ColourBy::AngleDefect;
}

std::vector<double> qualityValues(const SurfaceScene& scene, ColourBy by) {
    const std::vector<double>* measured = nullptr;
    switch (by) {
    case ColourBy::Developability:
        measured = &scene.polygonDevelopability;
        break;
    case ColourBy::Flatness:
        measured = &scene.polygonFlatness;
        break;
    case ColourBy::AngleDefect:
        measured = &scene.pointAngleDefect;
        break;
    case ColourBy::Patch:
        break;
    }
    if (measured == nullptr) {
        return {};
    }
    // Where a measure does not apply (triangles, the boundary) the colour is the scale's bottom.
    std::vector<double> values(measured->begin(), measured->end());
    for (double& v : values) {
        v = std::isnan(v) ? 0.0 : v;
    }
    return values;
}

std::vector<QColor> toleranceScale(double mark, int count) {
    std::vector<QColor> colours;
    for (int i = 0; i < count; ++i) {
        const double t = (i + 0.5) / count;
        if (t <= mark) {
            colours.push_back(
                QColor::fromHsvF(0.33f, 0.75f, static_cast<float>(0.55 + 0.25 * t / mark)));
        } else {
            const double above = (t - mark) / (1.0 - mark);
            colours.push_back(
                QColor::fromHsvF(static_cast<float>(0.16 * (1.0 - above)), 0.9f, 0.95f));
        }
    }
    return colours;
}

QualityColouring::QualityColouring()
    : m_tolerance(solver::Options{}.reportTolerance),
      m_table(vtkSmartPointer<vtkLookupTable>::New()) {
    m_table->SetScaleToLog10();
    m_table->SetTableRange(m_low, m_high);
    // Green up to the tolerance (developable), then yellow through orange to red (far from
    // developable), on the logarithmic scale.
    const double span = std::log10(m_high) - std::log10(m_low);
    const double mark = (std::log10(m_tolerance) - std::log10(m_low)) / span;
    m_colours = toleranceScale(mark, kColours);
    m_table->SetNumberOfTableValues(kColours);
    for (int i = 0; i < kColours; ++i) {
        const QColor& colour = m_colours[static_cast<std::size_t>(i)];
        m_table->SetTableValue(i, colour.redF(), colour.greenF(), colour.blueF(), 1.0);
    }
}

QString QualityColouring::toleranceLabel() {
    return QCoreApplication::translate("SceneView", "developable");
}

QualityColouring::Box QualityColouring::legendBox(int width, int height) {
    return {kLegendLeft * width, kLegendBottom * height, width - kLegendRightMargin,
            kLegendTop * height};
}

QualityColouring::~QualityColouring() = default;

void QualityColouring::setMode(ColourBy by) {
    m_mode = by;
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
    // The scale stays fixed (kScaleLow to kScaleHigh): values beyond it take its ends' colours.
}

double QualityColouring::valueOfPatch(const std::vector<SurfaceScene>& scenes, int surface,
                                      model::FaceId face) const {
    double value = std::numeric_limits<double>::quiet_NaN();
    if (m_mode == ColourBy::Patch) {
        return value;
    }
    const bool perPoint = isPerPoint(m_mode);
    std::size_t offset = 0; // of the scene's values in m_values
    for (const SurfaceScene& scene : scenes) {
        const std::size_t count = perPoint ? scene.points.size() : scene.polygons.size();
        if (scene.surface == surface && offset + count <= m_values.size()) {
            for (std::size_t p = 0; p < scene.polygons.size(); ++p) {
                if (scene.polygonFace[p] != face) {
                    continue;
                }
                if (!perPoint) {
                    value = std::isnan(value) ? m_values[offset + p]
                                              : std::max(value, m_values[offset + p]);
                    continue;
                }
                for (int point : scene.polygons[p]) {
                    const double v = m_values[offset + static_cast<std::size_t>(point)];
                    value = std::isnan(value) ? v : std::max(value, v);
                }
            }
        }
        offset += count;
    }
    return value;
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
