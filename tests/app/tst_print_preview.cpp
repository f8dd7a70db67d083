// File ▸ Print Preview shows what the PDF holds: a page drawn through the preview (the
// QPrintPreviewWidget's page, as the dialog shows it) and the same page of the exported PDF
// (rasterised by pdftoppm) are the same picture.
#include "io/pattern/page_plan.h"
#include "io/pattern/pattern_writers.h"
#include "model/examples.h"
#include "model/pattern/cutting_pattern.h"
#include "problem_text.h"
#include "reactions/pattern_reactions.h"
#include "test_registry.h"

#include <QGraphicsItem>
#include <QGraphicsScene>
#include <QGraphicsView>
#include <QImage>
#include <QPainter>
#include <QPrintPreviewWidget>
#include <QPrinter>
#include <QProcess>
#include <QTemporaryDir>
#include <QTest>

#include <algorithm>
#include <vector>

using namespace devsurf;

namespace {

// About the print preview's zoom on a screen: the pens of thin lines are below a pixel, where
// Qt's raster engine draws pen dash patterns in pixels (at 200 dpi the two agreed before).
constexpr int kDpi = 100;

// Page `page` (0-based) of the preview widget, drawn at kDpi as the preview draws it: the page's
// recorded picture replayed through a scaled painter.
QImage previewPage(QPrintPreviewWidget& preview, QPrinter& printer, int page) {
    auto* view = preview.findChild<QGraphicsView*>();
    if (view == nullptr || view->scene() == nullptr) {
        return {};
    }
    // The page items, in page order (top to bottom in the single-page layout).
    QList<QGraphicsItem*> pages = view->scene()->items();
    std::sort(pages.begin(), pages.end(), [](const QGraphicsItem* a, const QGraphicsItem* b) {
        return a->pos().y() < b->pos().y();
    });
    if (page >= pages.size()) {
        return {};
    }
    // An item is the paper (in printer pixels) with a border for its shadow around it.
    const QGraphicsItem* item = pages[page];
    const QRectF bounds = item->boundingRect();
    const double border = -bounds.left();
    const QRectF paper(item->pos(), bounds.size() - QSizeF(2 * border, 2 * border));
    const double scale = double(kDpi) / printer.resolution();
    QImage image((paper.size() * scale).toSize(), QImage::Format_RGB32);
    image.fill(Qt::white);
    QPainter painter(&image);
    painter.setRenderHint(QPainter::Antialiasing);
    painter.setRenderHint(QPainter::SmoothPixmapTransform);
    view->scene()->render(&painter, QRectF(QPointF(0, 0), QSizeF(image.size())), paper);
    return image;
}

QImage pdfPage(const QString& pdf, int page, const QString& dir) {
    const QString prefix = dir + QStringLiteral("/pdf");
    QProcess process;
    process.start(QStringLiteral("pdftoppm"),
                  {QStringLiteral("-r"), QString::number(kDpi), QStringLiteral("-f"),
                   QString::number(page + 1), QStringLiteral("-l"), QString::number(page + 1),
                   QStringLiteral("-png"), QStringLiteral("-singlefile"), pdf, prefix});
    if (!process.waitForFinished(60000) || process.exitCode() != 0) {
        return {};
    }
    return QImage(prefix + QStringLiteral(".png")).convertToFormat(QImage::Format_RGB32);
}

// The ink of a page (255 − grey, summed) in blocks of kBlock × kBlock pixels, starting
// `offset` pixels in: two renderers anti-alias text and edges differently within a block, but
// put the same ink into it.
constexpr int kBlock = 8;

std::vector<long> blockInk(const QImage& image, QPoint offset, int columns, int rows) {
    std::vector<long> ink(std::size_t(columns) * std::size_t(rows), 0);
    for (int r = 0; r < rows; ++r) {
        for (int c = 0; c < columns; ++c) {
            long sum = 0;
            for (int y = 0; y < kBlock; ++y) {
                for (int x = 0; x < kBlock; ++x) {
                    sum += 255 - qGray(image.pixel(offset.x() + c * kBlock + x,
                                                   offset.y() + r * kBlock + y));
                }
            }
            ink[std::size_t(r) * std::size_t(columns) + std::size_t(c)] = sum;
        }
    }
    return ink;
}

struct Difference {
    int blocks = 0;   // blocks whose ink differs by more than a quarter of a line through them
    double ink = 0.0; // total ink of b over a
};

// How two pictures of a page differ in `region` (pixels, at least 3 from the edges), shifted
// against each other by at most 3 pixels as matches best (the renderers round the page's position
// differently).
Difference difference(const QImage& a, const QImage& b, const QRect& region) {
    constexpr int kShift = 3;
    const int columns = region.width() / kBlock;
    const int rows = region.height() / kBlock;
    const std::vector<long> inkA = blockInk(a, region.topLeft(), columns, rows);
    long totalA = 0;
    for (long v : inkA) {
        totalA += v;
    }
    Difference best{columns * rows, 0.0};
    for (int sy = -kShift; sy <= kShift; ++sy) {
        for (int sx = -kShift; sx <= kShift; ++sx) {
            const std::vector<long> inkB =
                blockInk(b, region.topLeft() + QPoint(sx, sy), columns, rows);
            Difference d;
            long totalB = 0;
            for (std::size_t k = 0; k < inkA.size(); ++k) {
                // A 1-pixel line across a block at full black: 8 × 255 ink.
                d.blocks += std::abs(inkA[k] - inkB[k]) > 2 * 255 ? 1 : 0;
                totalB += inkB[k];
            }
            d.ink = totalA > 0 ? double(totalB) / double(totalA) : 1.0;
            if (d.blocks < best.blocks) {
                best = d;
            }
        }
    }
    return best;
}

} // namespace

class TstPrintPreview : public QObject {
    Q_OBJECT

private slots:
    void thePreviewDrawsWhatThePdfHolds() {
        // fig8 with its rulings as score lines: every kind of line on its tiles.
        model::PatternOptions options;
        options.rulings = true;
        options.sheetSize = {300.0, 200.0};
        const model::CuttingPattern pattern =
            model::buildCuttingPattern(model::makeExample("fig8", 0), options);
        QVERIFY(!pattern.pieces.empty());

        QTemporaryDir dir;
        QVERIFY(dir.isValid());
        const QString pdf = dir.filePath(QStringLiteral("fig8.pdf"));
        io::PatternWriteOptions write;
        write.paper = io::Paper::A4;
        write.problemTexts = app::patternProblemTexts(pattern);
        QVERIFY(io::savePatternFile(pattern, io::PatternFormat::Pdf, pdf, write));

        QPrinter printer(QPrinter::HighResolution);
        printer.setPageSize(QPageSize(QPageSize::A4));
        QPrintPreviewWidget preview(&printer);
        connect(&preview, &QPrintPreviewWidget::paintRequested, &preview,
                [&pattern, &preview](QPrinter* target) {
                    app::printCuttingPattern(*target, pattern, &preview);
                });
        preview.updatePreview();
        QVERIFY(preview.pageCount() >= 3);

        // The tiles: the pattern at 1:1 in the content area, where every kind of line is drawn
        // (the band's text is the renderers' own business).
        const io::PagePlan plan = io::planPages(pattern, io::paperSize(io::Paper::A4));
        const double px = kDpi / 25.4;
        const QRect content = QRectF(plan.contentOrigin.x * px, plan.contentOrigin.y * px,
                                     plan.content.x * px, plan.content.y * px)
                                  .toAlignedRect()
                                  .adjusted(3, 3, -3, -3);
        const int tiles = int(plan.tiles.size());
        QVERIFY(tiles >= 2 && preview.pageCount() > tiles);
        const QString keep = qEnvironmentVariable("DEVSURF_KEEP_IMAGES");
        for (int page = preview.pageCount() - tiles; page < preview.pageCount(); ++page) {
            const QImage shown = previewPage(preview, printer, page);
            const QImage printed = pdfPage(pdf, page, dir.path());
            QVERIFY(!shown.isNull() && !printed.isNull());
            QVERIFY(std::abs(shown.width() - printed.width()) <= 2);
            QVERIFY(std::abs(shown.height() - printed.height()) <= 2);
            if (!keep.isEmpty()) {
                shown.save(keep + QStringLiteral("/preview%1.png").arg(page));
                printed.save(keep + QStringLiteral("/pdf%1.png").arg(page));
            }
            const Difference d = difference(shown, printed, content);
            qInfo("page %d: %d blocks differ, ink of the PDF / preview %.3f", page + 1, d.blocks,
                  d.ink);
            // The same lines, dashes and dots: as much ink (the PDF's hairlines rasterise a
            // little darker; the preview's pixel-counted score dashes had half as much again),
            // and hardly a millimetre block differing.
            QVERIFY2(d.ink > 0.85 && d.ink < 1.3, qPrintable(QString::number(d.ink)));
            const int blocks = (content.width() / kBlock) * (content.height() / kBlock);
            QVERIFY2(d.blocks < blocks / 100, qPrintable(QString::number(d.blocks)));
        }
    }
};

DEVSURF_REGISTER_TEST(TstPrintPreview);
#include "tst_print_preview.moc"
