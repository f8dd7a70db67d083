#include "quality_colours.h"

#include <vtkLookupTable.h>
#include <vtkRenderer.h>
#include <vtkScalarBarActor.h>
#include <vtkTextProperty.h>
#include <vtkUnsignedCharArray.h>

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
