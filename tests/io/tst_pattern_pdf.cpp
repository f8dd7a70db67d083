#include "io/pattern/page_plan.h"
#include "io/pattern/pattern_painter.h"
#include "io/pattern/pattern_writers.h"
#include "pattern_fixtures.h"
#include "pattern_test_util.h"
#include "test_registry.h"

#include <QDir>
#include <QImage>
#include <QPrinter>
#include <QRegularExpression>
#include <QTemporaryDir>
#include <QTest>

#include <algorithm>
#include <cmath>

using namespace devsurf;

namespace {

struct PdfInfo {
    int pages = 0;
    double width = 0;  // points
    double height = 0; // points
};

PdfInfo pdfInfo(const QString& file) {
    const test::ToolRun run = test::runTool(QStringLiteral("pdfinfo"), {file});
    PdfInfo info;
    const QRegularExpression pages(QStringLiteral("Pages:\\s+(\\d+)"));
    const QRegularExpression size(QStringLiteral("Page size:\\s+([0-9.]+) x ([0-9.]+) pts"));
    if (auto m = pages.match(run.out); m.hasMatch()) {
        info.pages = m.captured(1).toInt();
    }
    if (auto m = size.match(run.out); m.hasMatch()) {
        info.width = m.captured(1).toDouble();
        info.height = m.captured(2).toDouble();
    }
    return info;
}

// Renders one page at 300 dpi with poppler.
QImage renderPage(const QString& file, int page, const QString& prefix) {
    const test::ToolRun run =
        test::runTool(QStringLiteral("pdftoppm"),
                      {QStringLiteral("-r"), QStringLiteral("300"), QStringLiteral("-png"),
                       QStringLiteral("-singlefile"), QStringLiteral("-f"), QString::number(page),
                       QStringLiteral("-l"), QString::number(page), file, prefix});
    if (!run.finished || run.exitCode != 0) {
        return {};
    }
    return QImage(prefix + QStringLiteral(".png")).convertToFormat(QImage::Format_Grayscale8);
}

// Sizes in mm of the bounding boxes of connected dark shapes that are roughly square and between
// `low` and `high` mm wide.
QList<QSizeF> squaresBetween(const QImage& image, double low, double high) {
    const int w = image.width();
    const int h = image.height();
    const double mmPerPixel = 25.4 / 300.0;
    std::vector<char> seen(std::size_t(w) * h, 0);
    auto dark = [&](int x, int y) { return image.constScanLine(y)[x] < 128; };
    QList<QSizeF> found;
    std::vector<QPoint> stack;
    for (int y0 = 0; y0 < h; ++y0) {
        for (int x0 = 0; x0 < w; ++x0) {
            if (seen[std::size_t(y0) * w + x0] || !dark(x0, y0)) {
                continue;
            }
            int x1 = x0, x2 = x0, y1 = y0, y2 = y0;
            stack.assign(1, QPoint(x0, y0));
            seen[std::size_t(y0) * w + x0] = 1;
            while (!stack.empty()) {
                const QPoint p = stack.back();
                stack.pop_back();
                x1 = std::min(x1, p.x());
                x2 = std::max(x2, p.x());
                y1 = std::min(y1, p.y());
                y2 = std::max(y2, p.y());
                for (const QPoint d : {QPoint(1, 0), QPoint(-1, 0), QPoint(0, 1), QPoint(0, -1)}) {
                    const QPoint q = p + d;
                    if (q.x() < 0 || q.y() < 0 || q.x() >= w || q.y() >= h) {
                        continue;
                    }
                    char& s = seen[std::size_t(q.y()) * w + q.x()];
                    if (!s && dark(q.x(), q.y())) {
                        s = 1;
                        stack.push_back(q);
                    }
                }
            }
            const QSizeF size((x2 - x1 + 1) * mmPerPixel, (y2 - y1 + 1) * mmPerPixel);
            if (size.width() > low && size.width() < high && size.height() > low &&
                size.height() < high && std::abs(size.width() - size.height()) < 2.0) {
                found << size;
            }
        }
    }
    return found;
}

void checkScaleSquares(const QImage& page, const char* what) {
    QVERIFY2(!page.isNull(), what);
    const QList<QSizeF> big = squaresBetween(page, 45.0, 55.0);
    QCOMPARE(big.size(), qsizetype(1));
    QVERIFY2(std::abs(big[0].width() - 50.0) <= 0.2 && std::abs(big[0].height() - 50.0) <= 0.2,
             qPrintable(QStringLiteral("%1 × %2").arg(big[0].width()).arg(big[0].height())));
    const QList<QSizeF> inch = squaresBetween(page, 23.0, 28.0);
    QCOMPARE(inch.size(), qsizetype(1));
    QVERIFY(std::abs(inch[0].width() - 25.4) <= 0.2 && std::abs(inch[0].height() - 25.4) <= 0.2);
    qInfo("%s: scale square measured %.3f × %.3f mm, inch square %.3f × %.3f mm", what,
          big[0].width(), big[0].height(), inch[0].width(), inch[0].height());
}

} // namespace

class TstPatternPdf : public QObject {
    Q_OBJECT
    QTemporaryDir m_dir;

private slots:
    void tilesCoverEverySheetWithOverlap() {
        const model::CuttingPattern pattern = test::fixturePattern();
        const io::PagePlan plan = io::planPages(pattern, {210.0, 297.0});
        // A4 less 10 mm margins and the 58 mm band: 190 × 219 mm portrait, 219 × 190 landscape.
        // The 500 mm sector needs 3 × 3 tiles either way (steps of 180 and 209 mm with a 10 mm
        // overlap), the 120 × 85 mm piece one page: portrait wins the tie.
        QVERIFY(!plan.landscape);
        QCOMPARE(plan.content.x, 190.0);
        QCOMPARE(plan.content.y, 219.0);
        QCOMPARE(plan.tiles.size(), std::size_t(10));
        QCOMPARE(plan.rows[0], 3);
        QCOMPARE(plan.columns[0], 3);
        for (const io::PageTile& tile : plan.tiles) {
            if (tile.group != 0) {
                continue;
            }
            QCOMPARE(tile.origin.x, 50.0 + tile.column * 180.0);
            QCOMPARE(tile.origin.y, 550.0 - tile.row * 209.0);
            // The last tiles reach past the sector's far edges.
            QVERIFY(50.0 + 2 * 180.0 + 190.0 >= 550.0 && 550.0 - 2 * 209.0 - 219.0 <= 50.0);
        }
        QCOMPARE(plan.tiles[5].label, std::string("B3"));

        // A 400 × 150 mm piece: 3 pages portrait (steps of 180 mm), 2 landscape (209 mm).
        model::CuttingPattern strip = pattern;
        strip.pieces.resize(1);
        auto squeeze = [](model::Vec2& p) {
            p = {300.0 + (p.x - 300.0) * 0.8, 300.0 + (p.y - 300.0) * 0.3};
        };
        std::for_each(strip.pieces[0].outline.begin(), strip.pieces[0].outline.end(), squeeze);
        for (model::PatternPath& path : strip.pieces[0].paths) {
            std::for_each(path.points.begin(), path.points.end(), squeeze);
        }
        for (model::PatternLabel& label : strip.pieces[0].labels) {
            squeeze(label.position);
        }
        const io::PagePlan stripPlan = io::planPages(strip, {210.0, 297.0});
        QVERIFY(stripPlan.landscape);
        QCOMPARE(stripPlan.tiles.size(), std::size_t(2));
    }

    void pdfIsTiledOnA4AtTrueScale() {
        const QString file = m_dir.filePath(QStringLiteral("p.pdf"));
        io::PatternWriteOptions options;
        options.paper = io::Paper::A4;
        int calls = 0;
        QVERIFY(io::savePatternFile(test::fixturePattern(), io::PatternFormat::Pdf, file, options,
                                    [&calls](int, int) { return ++calls > 0; }));
        const PdfInfo info = pdfInfo(file);
        // Report, overview of each sheet, 9 + 1 tiles.
        QCOMPARE(info.pages, 1 + 2 + 10);
        QCOMPARE(calls, info.pages);
        QVERIFY(std::abs(info.width - 595.28) < 0.5 && std::abs(info.height - 841.89) < 0.5);
        const test::ToolRun text =
            test::runTool(QStringLiteral("pdftotext"),
                          {QStringLiteral("-f"), QStringLiteral("1"), QStringLiteral("-l"),
                           QStringLiteral("1"), file, QStringLiteral("-")});
        QVERIFY(text.out.contains(QStringLiteral("Fabrication report")));
        QVERIFY(text.out.contains(QStringLiteral("120.0 × 85.0")));
        // Page 3: the first tile of the sector; the squares are on the report page too.
        checkScaleSquares(renderPage(file, 3, m_dir.filePath(QStringLiteral("pdf-page"))),
                          "PDF (QPdfWriter)");
        checkScaleSquares(renderPage(file, 1, m_dir.filePath(QStringLiteral("pdf-report"))),
                          "PDF report page");
    }

    void tilesCarryALegendAndTheFoldAngles() {
        const QString file = m_dir.filePath(QStringLiteral("legend.pdf"));
        QVERIFY(io::savePatternFile(test::fixturePattern(), io::PatternFormat::Pdf, file, {}));
        const int pages = pdfInfo(file).pages;
        auto pageText = [&file](int page) {
            return test::runTool(QStringLiteral("pdftotext"),
                                 {QStringLiteral("-f"), QString::number(page), QStringLiteral("-l"),
                                  QString::number(page), file, QStringLiteral("-")})
                .out;
        };
        // The last page: the one tile of the rectangle, with its 90° valley fold.
        const QString tile = pageText(pages);
        for (const char* line : {"Cut", "Mountain", "Valley", "Crease", "Seam", "Score"}) {
            QVERIFY2(tile.contains(QString::fromLatin1(line)), line);
        }
        QVERIFY2(tile.contains(QStringLiteral("V 90.0°")), qPrintable(tile));
        // The sector's tiles name its 20° mountain and valley folds.
        QString sector;
        for (int page = 4; page < pages; ++page) {
            sector += pageText(page);
        }
        QVERIFY(sector.contains(QStringLiteral("M 20.0°")));
        QVERIFY(sector.contains(QStringLiteral("V 20.0°")));
        // The report page is no tile: no legend there.
        QVERIFY(!pageText(1).contains(QStringLiteral("Mountain")));
    }

    void cancellingKeepsNoFile() {
        const QString file = m_dir.filePath(QStringLiteral("cancelled.pdf"));
        QVERIFY(!io::savePatternFile(test::fixturePattern(), io::PatternFormat::Pdf, file, {},
                                     [](int done, int) { return done < 3; }));
        QVERIFY(!QFile::exists(file));
    }

    void printPathRendersThroughQPrinter() {
        const model::CuttingPattern pattern = test::fixturePattern();
        const QString file = m_dir.filePath(QStringLiteral("printed.pdf"));
        QPrinter printer(QPrinter::HighResolution);
        printer.setOutputFormat(QPrinter::PdfFormat);
        printer.setOutputFileName(file);
        printer.setFullPage(true);
        const QPageSize a3(QPageSize::A3);
        const QSizeF paper = a3.size(QPageSize::Millimeter);
        const io::PagePlan plan = io::planPages(pattern, {paper.width(), paper.height()});
        io::preparePagedDevice(printer, a3, plan);
        QVERIFY(io::paintPatternPages(printer, pattern, plan, {}));
        const PdfInfo info = pdfInfo(file);
        QCOMPARE(info.pages, io::patternPageCount(pattern, plan));
        // A3 (297 × 420 mm): content 277 × 342 portrait or 342 × 277 landscape: the sector
        // needs 2 × 2 tiles in either, so 1 + 2 + 4 + 1 pages.
        QCOMPARE(info.pages, 8);
        const double shortSide = std::min(info.width, info.height);
        const double longSide = std::max(info.width, info.height);
        QVERIFY(std::abs(shortSide - 841.89) < 0.5 && std::abs(longSide - 1190.55) < 0.5);
        checkScaleSquares(renderPage(file, 3, m_dir.filePath(QStringLiteral("printer-page"))),
                          "Print path (QPrinter)");
    }
};

DEVSURF_REGISTER_TEST(TstPatternPdf);
#include "tst_pattern_pdf.moc"
