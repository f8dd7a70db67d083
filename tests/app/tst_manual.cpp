// The manual matches the product: it lists every built-in example with a line of its own, in
// English and Japanese, and every picture it and README.md show exists.
#include "model/examples.h"
#include "test_registry.h"

#include <QDir>
#include <QFile>
#include <QFileInfo>
#include <QRegularExpression>
#include <QTest>

namespace {

QString readText(const QString& path) {
    QFile file(path);
    return file.open(QIODevice::ReadOnly) ? QString::fromUtf8(file.readAll()) : QString();
}

} // namespace

class TstManual : public QObject {
    Q_OBJECT

private slots:
    void everyExampleHasItsLine_data() {
        QTest::addColumn<QString>("manual");
        QTest::newRow("English") << QStringLiteral("docs/manual/manual.md");
        QTest::newRow("Japanese") << QStringLiteral("docs/manual/manual_ja.md");
    }

    void everyExampleHasItsLine() {
        QFETCH(QString, manual);
        const QString text = readText(QDir(QStringLiteral(DEVSURF_SOURCE_DIR)).filePath(manual));
        QVERIFY(!text.isEmpty());
        QVERIFY(devsurf::model::builtInExamples().size() >= 6);
        for (const devsurf::model::ExampleInfo& info : devsurf::model::builtInExamples()) {
            const QString line =
                QStringLiteral("\n- `%1`: ").arg(QString::fromStdString(info.name));
            QVERIFY2(text.contains(line), qPrintable(manual + QStringLiteral(" lacks ") + line));
        }
    }

    void everyPictureShownExists_data() {
        QTest::addColumn<QString>("page");
        QTest::newRow("README") << QStringLiteral("README.md");
        QTest::newRow("manual") << QStringLiteral("docs/manual/manual.md");
        QTest::newRow("manual ja") << QStringLiteral("docs/manual/manual_ja.md");
    }

    void everyPictureShownExists() {
        QFETCH(QString, page);
        const QDir source(QStringLiteral(DEVSURF_SOURCE_DIR));
        const QString text = readText(source.filePath(page));
        QVERIFY(!text.isEmpty());
        const QDir base = QFileInfo(source.filePath(page)).dir();
        const QRegularExpression image(QStringLiteral("!\\[[^\\]]*\\]\\(([^)]+)\\)"));
        int pictures = 0;
        for (const QRegularExpressionMatch& match : image.globalMatch(text)) {
            ++pictures;
            QVERIFY2(QFileInfo::exists(base.filePath(match.captured(1))),
                     qPrintable(match.captured(1)));
        }
        QVERIFY(pictures > 0);
    }
};

DEVSURF_REGISTER_TEST(TstManual);
#include "tst_manual.moc"
