// Curves of an SVG drawing: Qt's SVG renderer draws the file into a paint engine that keeps the
// outlines it is given (paths, polygons, rectangles, ellipses, lines) instead of pixels, so
// every shape, transform and unit the renderer understands arrives here as a QPainterPath in
// the drawing's user units. Those are scaled to mm from the root's width, height and viewBox,
// flipped so that y points up (as the drawing is seen), and sampled within the tolerance.

#include "curve_import.h"

#include <QByteArray>
#include <QLoggingCategory>
#include <QPaintDevice>
#include <QPaintEngine>
#include <QPainter>
#include <QPainterPath>
#include <QRegularExpression>
#include <QSvgRenderer>
#include <QXmlStreamReader>
#include <QXmlStreamWriter>

#include <algorithm>
#include <cmath>

namespace devsurf::io {

namespace {

using Code = CurveImportError::Code;

// A length attribute ("300mm", "21cm", "8.5in", "600", "600px") in mm; nullopt if it has
// none or a relative unit (%, em), which give no absolute size.
std::optional<double> lengthInMm(const QString& text) {
    static const QRegularExpression pattern(
        QStringLiteral(R"(^\s*([+-]?(?:\d+\.?\d*|\.\d+)(?:[eE][+-]?\d+)?)\s*([a-z]*)\s*$)"));
    const QRegularExpressionMatch match = pattern.match(text);
    if (!match.hasMatch()) {
        return std::nullopt;
    }
    const double value = match.captured(1).toDouble();
    const QString unit = match.captured(2);
    double mm = 0.0;
    if (unit == QLatin1String("mm")) {
        mm = 1.0;
    } else if (unit == QLatin1String("cm")) {
        mm = 10.0;
    } else if (unit == QLatin1String("in")) {
        mm = 25.4;
    } else if (unit == QLatin1String("pt")) {
        mm = 25.4 / 72.0;
    } else if (unit == QLatin1String("pc")) {
        mm = 25.4 / 6.0;
    } else if (unit.isEmpty() || unit == QLatin1String("px")) {
        mm = 25.4 / 96.0; // CSS pixels
    } else {
        return std::nullopt;
    }
    if (!std::isfinite(value) || value <= 0.0) {
        return std::nullopt;
    }
    return value * mm;
}

// mm per user unit, from the root element's attributes: width over the viewBox's width (each
// axis alike; SVG keeps the aspect ratio by default), or CSS pixels without a size.
double millimetresPerUnit(const QXmlStreamAttributes& attributes) {
    const std::optional<double> width = lengthInMm(attributes.value("width").toString());
    const QStringList box = attributes.value("viewBox").toString().split(
        QRegularExpression(QStringLiteral("[\\s,]+")), Qt::SkipEmptyParts);
    const double boxWidth = box.size() == 4 ? box[2].toDouble() : 0.0;
    if (width && boxWidth > 0.0 && std::isfinite(boxWidth)) {
        return *width / boxWidth;
    }
    return 25.4 / 96.0; // user units are CSS pixels
}

// The drawing as the renderer gets it, in one pass over the document: its scale from the
// root, and the document without its text (text, and what only text holds), whose glyphs the
// renderer would draw as outlines that are no curves of the drawing.
struct Prepared {
    QByteArray drawing;
    double scale = 0.0; // mm per user unit
    QString problem;    // why it is not an SVG drawing; empty when it is
};

Prepared prepare(const QByteArray& bytes) {
    Prepared prepared;
    QXmlStreamReader reader(bytes);
    QXmlStreamWriter writer(&prepared.drawing);
    bool root = true;
    int skipping = 0; // depth inside a skipped element
    while (!reader.atEnd()) {
        reader.readNext();
        if (reader.hasError()) {
            prepared.problem = reader.errorString();
            return prepared;
        }
        if (reader.isStartElement() && root) {
            root = false;
            if (reader.name() != QLatin1String("svg")) {
                prepared.problem = QStringLiteral("the root element is not <svg>");
                return prepared;
            }
            prepared.scale = millimetresPerUnit(reader.attributes());
        }
        if (reader.isStartElement() && (skipping > 0 || reader.name() == QLatin1String("text") ||
                                        reader.name() == QLatin1String("flowRoot"))) {
            ++skipping;
            continue;
        }
        if (reader.isEndElement() && skipping > 0) {
            --skipping;
            continue;
        }
        if (skipping == 0 && reader.tokenType() != QXmlStreamReader::DTD) {
            writer.writeCurrentToken(reader);
        }
    }
    if (root) {
        prepared.problem = QStringLiteral("no <svg> element");
    }
    return prepared;
}

// A paint engine that records the outlines drawn, in user units (the painter's transform
// applied), and paints nothing. Text is not a curve and is left out.
class OutlineEngine : public QPaintEngine {
public:
    OutlineEngine() : QPaintEngine(QPaintEngine::AllFeatures) {}
    bool begin(QPaintDevice*) override { return true; }
    bool end() override { return true; }
    Type type() const override { return QPaintEngine::User; }
    void updateState(const QPaintEngineState& state) override {
        if (state.state() & QPaintEngine::DirtyTransform) {
            m_transform = state.transform();
        }
    }
    void drawPath(const QPainterPath& path) override {
        // A shape filled and stroked may arrive twice: kept once.
        QPainterPath mapped = m_transform.map(path);
        if (paths.empty() || paths.back() != mapped) {
            paths.push_back(std::move(mapped));
        }
    }
    void drawPolygon(const QPointF* points, int count, PolygonDrawMode mode) override {
        QPainterPath path;
        path.addPolygon(QPolygonF(QList<QPointF>(points, points + count)));
        if (mode != PolylineMode) {
            path.closeSubpath();
        }
        drawPath(path);
    }
    void drawPolygon(const QPoint* points, int count, PolygonDrawMode mode) override {
        QPolygonF polygon;
        for (int i = 0; i < count; ++i) {
            polygon << QPointF(points[i]);
        }
        drawPolygon(polygon.constData(), count, mode);
    }
    void drawRects(const QRectF* rects, int count) override {
        for (int i = 0; i < count; ++i) {
            QPainterPath path;
            path.addRect(rects[i]);
            drawPath(path);
        }
    }
    void drawEllipse(const QRectF& rect) override {
        QPainterPath path;
        path.addEllipse(rect);
        drawPath(path);
    }
    void drawLines(const QLineF* lines, int count) override {
        for (int i = 0; i < count; ++i) {
            QPainterPath path(lines[i].p1());
            path.lineTo(lines[i].p2());
            drawPath(path);
        }
    }
    void drawPixmap(const QRectF&, const QPixmap&, const QRectF&) override {}
    void drawTextItem(const QPointF&, const QTextItem&) override {}
    void drawImage(const QRectF&, const QImage&, const QRectF&, Qt::ImageConversionFlags) override {
    }

    std::vector<QPainterPath> paths;

private:
    QTransform m_transform;
};

class OutlineDevice : public QPaintDevice {
public:
    QPaintEngine* paintEngine() const override { return &engine; }
    mutable OutlineEngine engine;

protected:
    int metric(PaintDeviceMetric metric) const override {
        switch (metric) {
        case PdmWidth:
        case PdmHeight:
            return 1000;
        case PdmWidthMM:
        case PdmHeightMM:
            return 264;
        case PdmDpiX:
        case PdmDpiY:
        case PdmPhysicalDpiX:
        case PdmPhysicalDpiY:
            return 96;
        case PdmDevicePixelRatio:
            return 1;
        case PdmDevicePixelRatioScaled:
            return static_cast<int>(QPaintDevice::devicePixelRatioFScale());
        default:
            return 32; // PdmNumColors, PdmDepth
        }
    }
};

// A cubic Bézier sampled so that no chord is farther than `tolerance` from it: the chords of
// n equal parameter steps deviate at most max|B″|/(8n²), and |B″| ≤ 6·max(|p0−2p1+p2|,
// |p1−2p2+p3|).
void sampleCubic(QPointF p0, QPointF p1, QPointF p2, QPointF p3, // copies: out may be their source
                 double tolerance, std::vector<QPointF>& out) {
    const auto norm = [](const QPointF& v) { return std::hypot(v.x(), v.y()); };
    const double bend = 6.0 * std::max(norm(p0 - 2 * p1 + p2), norm(p1 - 2 * p2 + p3));
    // Clamped as a double: a hostile coordinate may make the bound infinite or not a number.
    const double wanted = std::ceil(std::sqrt(bend / (8.0 * tolerance)));
    const int n =
        std::isfinite(wanted)
            ? static_cast<int>(std::clamp(wanted, 1.0, static_cast<double>(kMaxCurvePoints)))
            : static_cast<int>(kMaxCurvePoints);
    for (int i = 1; i <= n; ++i) {
        const double t = static_cast<double>(i) / n, s = 1.0 - t;
        out.push_back(s * s * s * p0 + 3 * s * s * t * p1 + 3 * s * t * t * p2 + t * t * t * p3);
    }
}

} // namespace

CurveImportResult readSvgCurves(const QByteArray& bytes, const CurveImportOptions& options) {
    // A damaged drawing is reported in one sentence by the caller, not line by line by the
    // renderer.
    static const bool quiet = [] {
        QLoggingCategory::setFilterRules(QStringLiteral("qt.svg*=false"));
        return true;
    }();
    (void)quiet;
    const Prepared prepared = prepare(bytes);
    if (!prepared.problem.isEmpty()) {
        return curveImportFailure(Code::Damaged, prepared.problem.toStdString());
    }
    const double scale = prepared.scale;
    QSvgRenderer renderer;
    if (!renderer.load(prepared.drawing) || !renderer.isValid()) {
        return curveImportFailure(Code::Damaged, "the SVG renderer refused it");
    }
    if (options.progress && !options.progress(0.2)) {
        return curveImportFailure(Code::Cancelled);
    }
    OutlineDevice device;
    {
        QPainter painter(&device);
        // The viewBox onto itself: the painter's coordinates are the drawing's user units.
        const QRectF box = renderer.viewBoxF();
        renderer.render(&painter,
                        box.isValid() ? box : QRectF(QPointF(0, 0), renderer.defaultSize()));
    }
    if (options.progress && !options.progress(0.6)) {
        return curveImportFailure(Code::Cancelled);
    }
    // The tolerance in user units.
    const double tolerance = std::max(options.tolerance, 1e-6) / scale;
    CurveImportResult result;
    std::size_t total = 0;
    for (const QPainterPath& path : device.engine.paths) {
        std::vector<QPointF> points;
        const auto flush = [&] {
            if (points.size() >= 2 && total + points.size() <= 50 * kMaxCurvePoints) {
                model::ReferenceCurve curve;
                curve.name = "SVG path " + std::to_string(result.curves.size() + 1);
                bool finite = true;
                for (const QPointF& p : points) {
                    curve.points.emplace_back(p.x() * scale, -p.y() * scale, 0.0);
                    finite = finite && std::isfinite(curve.points.back().x) &&
                             std::isfinite(curve.points.back().y);
                }
                if (!finite) { // beyond what a double holds once in mm
                    ++result.skipped;
                    points.clear();
                    return;
                }
                total += points.size();
                result.curves.push_back(std::move(curve));
            } else if (points.size() >= 2) {
                ++result.skipped;
            }
            points.clear();
        };
        for (int i = 0; i < path.elementCount(); ++i) {
            const QPainterPath::Element e = path.elementAt(i);
            if (!std::isfinite(e.x) || !std::isfinite(e.y)) {
                return curveImportFailure(Code::Damaged, "a coordinate is not finite");
            }
            if (e.isMoveTo()) {
                flush();
                points.emplace_back(e.x, e.y);
            } else if (e.isLineTo()) {
                points.emplace_back(e.x, e.y);
            } else if (e.isCurveTo() && i + 2 < path.elementCount() && !points.empty()) {
                const QPainterPath::Element c2 = path.elementAt(i + 1);
                const QPainterPath::Element end = path.elementAt(i + 2);
                sampleCubic(points.back(), QPointF(e.x, e.y), QPointF(c2.x, c2.y),
                            QPointF(end.x, end.y), tolerance, points);
                i += 2;
            }
            if (points.size() > kMaxCurvePoints) {
                return curveImportFailure(Code::Damaged, "a curve has too many points");
            }
        }
        flush();
    }
    if (result.curves.empty()) {
        return curveImportFailure(Code::NoCurves);
    }
    if (options.progress && !options.progress(1.0)) {
        return curveImportFailure(Code::Cancelled);
    }
    return result;
}

} // namespace devsurf::io
