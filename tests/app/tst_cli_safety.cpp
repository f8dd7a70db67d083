// Issue 46 ("nothing lost, nothing hangs"): devsurf-cli run in process, as a hostile user and a
// careless script would run it. Device nodes are made with mknod and a full disk with a small
// tmpfs when the tests run as root; otherwise those parts are skipped with a message.

#include "devsurf_cli.h"
#include "far_design.h"
#include "io/file_error.h"
#include "io/project_file.h"
#include "model/examples.h"
#include "test_registry.h"

#include <QDir>
#include <QElapsedTimer>
#include <QFile>
#include <QFileInfo>
#include <QGuiApplication>
#include <QRandomGenerator>
#include <QTemporaryDir>
#include <QTest>

#include <sys/mount.h>
#include <sys/stat.h>
#include <sys/sysmacros.h>
#include <unistd.h>

#include <atomic>
#include <iostream>
#include <sstream>
#include <thread>

using namespace devsurf;

namespace {

struct SafeCliOutcome {
    int exitCode = -1;
    QString out;
    QString err;
};

// Runs devsurf-cli in this process, capturing what it prints on std::cout and std::cerr.
SafeCliOutcome safeCli(const QStringList& arguments) {
    std::vector<std::string> args;
    for (const QString& argument : arguments) {
        args.push_back(argument.toStdString());
    }
    std::ostringstream out;
    std::ostringstream err;
    std::streambuf* const oldOut = std::cout.rdbuf(out.rdbuf());
    std::streambuf* const oldErr = std::cerr.rdbuf(err.rdbuf());
    SafeCliOutcome outcome;
    outcome.exitCode = app::runDevsurfCli(args);
    std::cout.rdbuf(oldOut);
    std::cerr.rdbuf(oldErr);
    outcome.out = QString::fromStdString(out.str());
    outcome.err = QString::fromStdString(err.str());
    return outcome;
}

// One sentence (or a sentence and its list of problems) on stderr, as every failure ends.
bool isSentence(const QString& err) {
    return err.startsWith(QLatin1String("devsurf-cli: ")) && err.endsWith(QLatin1Char('\n')) &&
           err.size() > 20;
}

QByteArray bytesOf(const QString& path) {
    QFile file(path);
    return file.open(QIODevice::ReadOnly) ? file.readAll() : QByteArray();
}

bool isValidProject(const QString& path) {
    try {
        io::loadProjectFile(path);
        return true;
    } catch (const io::FileError&) {
        return false;
    }
}

struct stat statOf(const QString& path) {
    struct stat info {};
    ::lstat(QFile::encodeName(path).constData(), &info);
    return info;
}

} // namespace

class TstCliSafety : public QObject {
    Q_OBJECT
    QTemporaryDir m_dir;

    QString path(const QString& name) const { return m_dir.filePath(name); }

    QString project(const QString& name, const char* example = "annulus") {
        const QString file = path(name);
        io::saveProjectFile(model::makeExample(example), file, io::Backup::None);
        return file;
    }

private slots:
    // 1. An export over the project (or a link to it) is refused; the project stays.
    void exportOverTheProjectIsRefused() {
        const QString design = project("design.devsurf");
        const QByteArray before = bytesOf(design);
        QFile::link(design, path("link.svg"));
        QVERIFY(::link(QFile::encodeName(design).constData(),
                       QFile::encodeName(path("hard.json")).constData()) == 0);
        for (const QStringList& args :
             QList<QStringList>{{"export", design, "--format", "svg", "-o", design},
                                {"export", design, "--format", "dxf", "-o", design},
                                {"export", design, "--format", "svg", "-o", path("link.svg")},
                                {"export-json", design, "-o", design},
                                {"export-json", design, "-o", path("hard.json")}}) {
            const SafeCliOutcome run = safeCli(args);
            QVERIFY2(run.exitCode == 2, qPrintable(args.join(' ') + ": " + run.err));
            QVERIFY2(run.err.contains("the project being read"), qPrintable(run.err));
            QVERIFY(isSentence(run.err));
            QCOMPARE(bytesOf(design), before);
        }
        QVERIFY(isValidProject(design));
        // Project to project: an edit in place, the previous version kept as .bak.
        const SafeCliOutcome pin = safeCli({"pin", design, "--vertices", "0", "-o", design});
        QCOMPARE(pin.exitCode, 0);
        QVERIFY(isValidProject(design));
        QCOMPARE(bytesOf(design + ".bak"), before);
    }

    // 2. Devices, pipes, sockets and folders are never replaced; "-o -" is standard output.
    void nonRegularOutputsAreRefused() {
        const QString design = project("in.devsurf");
        QVERIFY(::mkfifo(QFile::encodeName(path("fifo")).constData(), 0600) == 0);
        QVERIFY(QDir(m_dir.path()).mkdir("folder.svg"));
        QStringList targets{path("fifo"), path("folder.svg")};
        const QString node = path("full-node");
        const bool root =
            ::mknod(QFile::encodeName(node).constData(), S_IFCHR | 0600, makedev(1, 7)) == 0;
        if (root) {
            targets << node;
        } else {
            qWarning("not root: the character device case is skipped (mknod needs root)");
        }
        for (const QString& target : targets) {
            const mode_t type = statOf(target).st_mode & S_IFMT;
            for (const QStringList& args :
                 QList<QStringList>{{"export", design, "--format", "svg", "-o", target},
                                    {"export", design, "--format", "fold", "-o", target},
                                    {"export-json", design, "-o", target},
                                    {"pin", design, "--vertices", "0", "-o", target},
                                    {"solve", design, "--iterations", "1", "-o", target},
                                    {"example", "sheet", "-o", target}}) {
                const SafeCliOutcome run = safeCli(args);
                QVERIFY2(run.exitCode == 2, qPrintable(args.join(' ') + ": " + run.err));
                QVERIFY(isSentence(run.err));
                QCOMPARE(statOf(target).st_mode & S_IFMT, type);
                QVERIFY(!QFileInfo::exists(target + ".bak"));
            }
        }
        const SafeCliOutcome svg = safeCli({"export", design, "--format", "svg", "-o", "-"});
        QCOMPARE(svg.exitCode, 0);
        QVERIFY(svg.out.startsWith("<?xml"));
        QVERIFY(svg.out.contains("<svg"));
        const SafeCliOutcome json = safeCli({"export-json", design, "-o", "-"});
        QCOMPARE(json.exitCode, 0);
        QVERIFY(json.out.contains("devsurf-interchange"));
        QCOMPARE(safeCli({"solve", design, "-o", "-"}).exitCode, 1);
        QVERIFY(!QFileInfo::exists("-"));
    }

    // 3. A device without an end is refused after its first bytes, not read to exhaustion.
    void endlessInputIsRefusedAtOnce() {
        if (!QFileInfo::exists("/dev/zero")) {
            QSKIP("no /dev/zero");
        }
        const SafeCliOutcome run = safeCli({"validate", "/dev/zero"});
        QCOMPARE(run.exitCode, 2);
        QVERIFY2(run.err.contains("not a DevSurf project file"), qPrintable(run.err));
        for (const char* command : {"info", "report"}) {
            QCOMPARE(safeCli({command, "/dev/zero"}).exitCode, 2);
        }
        // A pipe holding a project is read up to its stated length (and one byte more).
        const QString design = project("piped.devsurf", "sheet");
        const QString fifo = path("project-fifo");
        QVERIFY(::mkfifo(QFile::encodeName(fifo).constData(), 0600) == 0);
        const QByteArray bytes = bytesOf(design);
        std::thread writer([&] {
            QFile out(fifo);
            if (out.open(QIODevice::WriteOnly)) {
                out.write(bytes);
            }
        });
        const SafeCliOutcome piped = safeCli({"validate", fifo});
        writer.join();
        QVERIFY2(piped.exitCode == 0, qPrintable(piped.err));
    }

    // 4. The DXF writer needs no temporary folder (none is left when a run is killed). TMPDIR
    // names a file, in which no folder can be made (a missing TMPDIR is no test: Qt then makes
    // its folders in "/", which root may write).
    void dxfExportLeavesNothingBehind() {
        const QString design = project("dxf.devsurf");
        const QByteArray oldTemp = qgetenv("TMPDIR");
        QTemporaryDir temp;
        const QString notAFolder = temp.filePath("not-a-folder");
        QFile file(notAFolder);
        QVERIFY(file.open(QIODevice::WriteOnly));
        file.close();
        qputenv("TMPDIR", QFile::encodeName(notAFolder));
        const SafeCliOutcome run =
            safeCli({"export", design, "--format", "dxf", "-o", path("out.dxf")});
        qputenv("TMPDIR", oldTemp);
        QVERIFY2(run.exitCode == 0, qPrintable(run.err));
        QVERIFY(bytesOf(path("out.dxf")).contains("EOF"));
        QCOMPARE(QDir(temp.path()).entryList(QDir::NoDotAndDotDot | QDir::AllEntries),
                 QStringList{"not-a-folder"});
        QCOMPARE(QFileInfo(notAFolder).size(), 0);
        for (const QString& name : QDir(m_dir.path()).entryList({"out.dxf*"})) {
            QCOMPARE(name, QStringLiteral("out.dxf"));
        }
    }

    // 7. A design reaching far away (one control point at the validity limit, 1 km up) is
    // reported and exported in time proportional to the design, or refused at once.
    void farAwayGeometryAnswersAtOnce() {
        const model::Project far = test::farAnnulus();
        const QString file = path("far.devsurf");
        io::saveProjectFile(far, file, io::Backup::None);
        QVERIFY(isValidProject(file));
        for (const QStringList& args : QList<QStringList>{
                 {"report", file}, {"export", file, "--format", "svg", "-o", path("far.svg")}}) {
            QElapsedTimer timer;
            timer.start();
            const SafeCliOutcome run = safeCli(args);
            const qint64 ms = timer.elapsed();
            // The examples take 0.1 to 0.3 s; before the check this one took 9 s.
            QVERIFY2(ms < 4000, qPrintable(args.join(' ') + ": " + QString::number(ms) + " ms"));
            QCOMPARE(run.exitCode, 2);
            QVERIFY2(isSentence(run.err) && run.err.contains("--tolerance"), qPrintable(run.err));
            // The tolerance it names does the job.
            const QString advice = run.err.mid(run.err.indexOf("--tolerance ") + 12);
            const QString tolerance = advice.left(advice.indexOf(' '));
            const SafeCliOutcome coarser = safeCli(args + QStringList{"--tolerance", tolerance});
            QVERIFY2(coarser.exitCode == 0, qPrintable(tolerance + ": " + coarser.err));
        }
    }

    // 8. A full disk is named as such, for every format.
    void fullDiskSaysWhy() {
        const QString design = project("full.devsurf");
        QTemporaryDir mountPoint;
        const QByteArray where = QFile::encodeName(mountPoint.path());
        if (::mount("tmpfs", where.constData(), "tmpfs", 0, "size=16k") != 0) {
            QSKIP("cannot mount a small tmpfs (needs root): the full-disk case is skipped");
        }
        const QDir full(mountPoint.path());
        QList<QStringList> cases{
            {"export", design, "--format", "svg", "-o", full.filePath("p.svg")},
            {"export", design, "--format", "dxf", "-o", full.filePath("p.dxf")},
            {"export", design, "--format", "fold", "-o", full.filePath("p.fold")},
            {"export-json", design, "-o", full.filePath("p.json")},
            {"solve", design, "--iterations", "1", "-o", full.filePath("p.devsurf")}};
        if (qobject_cast<QGuiApplication*>(QCoreApplication::instance()) != nullptr) {
            cases.append({"export", design, "--format", "pdf", "-o", full.filePath("p.pdf")});
        }
        QStringList failures;
        for (const QStringList& args : cases) {
            const SafeCliOutcome run = safeCli(args);
            if (run.exitCode != 2 || !run.err.contains("No space left on device")) {
                failures << args.join(' ') + ": " + QString::number(run.exitCode) + " " + run.err;
            }
        }
        ::umount(where.constData());
        QVERIFY2(failures.isEmpty(), qPrintable(failures.join('\n')));
    }

    // 9. A save always leaves a backup: the old one stays until the new one is complete.
    void backupNeverVanishes() {
        const QString file = path("saved.devsurf");
        const model::Project big = model::makeExample("annulus", 20);
        io::saveProjectFile(big, file);
        io::saveProjectFile(big, file);
        const QString backup = file + ".bak";
        QVERIFY(QFileInfo::exists(backup));
        std::atomic<bool> done{false};
        std::thread saver([&] {
            for (int i = 0; i < 30; ++i) {
                io::saveProjectFile(big, file);
            }
            done = true;
        });
        int looks = 0;
        int missing = 0;
        const QByteArray name = QFile::encodeName(backup);
        while (!done) {
            ++looks;
            missing += ::access(name.constData(), F_OK) != 0 ? 1 : 0;
        }
        saver.join();
        QVERIFY(looks > 0);
        QCOMPARE(missing, 0);
        QVERIFY(isValidProject(backup));
    }

    // 10. A pattern format written into another format's file name is refused.
    void extensionOfAnotherFormatIsRefused() {
        const QString design = project("ext.devsurf");
        for (const QStringList& args :
             QList<QStringList>{{"export", design, "--format", "svg", "-o", path("x.pdf")},
                                {"export", design, "--format", "dxf", "-o", path("x.svg")},
                                {"export", design, "--format", "pdf", "-o", path("x.devsurf")},
                                {"export-json", design, "-o", path("x.svg")}}) {
            const SafeCliOutcome run = safeCli(args);
            QVERIFY2(run.exitCode == 1, qPrintable(args.join(' ') + ": " + run.err));
            QVERIFY(run.err.contains("ends in ."));
            QVERIFY(!QFileInfo::exists(args.last()));
        }
        QCOMPARE(safeCli({"export", design, "--format", "svg", "-o", path("x.SVG")}).exitCode, 0);
        QCOMPARE(safeCli({"export", design, "--format", "svg", "-o", path("x.txt")}).exitCode, 0);
    }

    // Every subcommand has its own --help.
    void everySubcommandHasHelp() {
        for (const char* command :
             {"example", "info", "pin", "crease", "smooth", "validate", "export-json", "examples",
              "solve", "drag", "export", "report"}) {
            const SafeCliOutcome run = safeCli({command, "--help"});
            QCOMPARE(run.exitCode, 0);
            QVERIFY2(run.out.startsWith(QStringLiteral("Usage: devsurf-cli ") + command),
                     qPrintable(run.out));
            QVERIFY(run.out.contains("--help"));
        }
    }

    // Random argument lists to every subcommand: each run ends with exit 1 or 2 and a sentence,
    // or with exit 0 and a readable output, never a crash or a hang.
    void fuzzTheCommandLine() {
        const QString sheet = project("fuzz.devsurf", "sheet");
        const QString out = path("fuzz-out");
        QDir(m_dir.path()).mkdir("fuzz-folder");
        // A random value after a random -o names a file relative to the working directory:
        // the test's own directory, not wherever the test runs from.
        struct WorkingDirectory {
            QString previous = QDir::currentPath();
            ~WorkingDirectory() { QDir::setCurrent(previous); }
        } restore;
        QVERIFY(QDir::setCurrent(m_dir.path()));
        const QStringList commands{"example",  "info",        "pin",      "crease", "smooth",
                                   "validate", "export-json", "examples", "solve",  "drag",
                                   "export",   "report",      "bogus",    ""};
        const QStringList options{
            "--vertices", "--edges",   "--condition", "--surface",      "--unpin",
            "--off",      "--json",    "--samples",   "--iterations",   "--perturb",
            "--seed",     "--fix",     "--crease",    "--by",           "--rotate",
            "--steps",    "--pin",     "--after",     "--keep-lengths", "--stretch",
            "--format",   "--sheet",   "--paper",     "--tolerance",    "--seam",
            "--rulings",  "--splines", "--r12",       "--size",         "-o",
            "-x",         "--"};
        const QStringList values{"0",
                                 "1",
                                 "2",
                                 "3",
                                 "999",
                                 "-1",
                                 "4294967295",
                                 "4294967296",
                                 "1e308",
                                 "-1e308",
                                 "nan",
                                 "inf",
                                 "-inf",
                                 "0x10",
                                 " 3",
                                 "3 ",
                                 "",
                                 ",",
                                 "1,,2",
                                 "1,2,",
                                 "0,0",
                                 "1,1",
                                 "0,1,2,3",
                                 "0,0,0",
                                 "0,0,1",
                                 "0,0,1e308",
                                 "nan,0,0",
                                 "1,2",
                                 "0,0,0,0,0,0,30",
                                 "0,0,0,0,0,1,30",
                                 "0,0,0,1e308,0,0,30",
                                 "0,0,0,0,0,1,1e308",
                                 "100000",
                                 "10001",
                                 "99999999999999999999",
                                 "svg",
                                 "dxf",
                                 "pdf",
                                 "fold",
                                 "png",
                                 "A4",
                                 "B5",
                                 "600,400",
                                 "0,0",
                                 "curved-fold",
                                 "none",
                                 "sheet",
                                 "annulus",
                                 "-",
                                 "abc",
                                 "1e-300"};
        QRandomGenerator random(46);
        int cases = 0;
        int succeeded = 0;
        for (int n = 0; n < 2500; ++n) {
            QStringList args;
            const QString command = commands[random.bounded(commands.size())];
            if (!command.isEmpty()) {
                args << command;
            }
            if (random.bounded(4) != 0) {
                args << (random.bounded(8) == 0 ? path("nothing.devsurf") : sheet);
            }
            const int count = random.bounded(6);
            for (int i = 0; i < count; ++i) {
                args << options[random.bounded(options.size())];
                if (random.bounded(5) != 0) {
                    args << values[random.bounded(values.size())];
                }
            }
            if (random.bounded(3) != 0) {
                const int target = random.bounded(6);
                args << "-o"
                     << (target == 0   ? out + ".devsurf"
                         : target == 1 ? out + ".svg"
                         : target == 2 ? sheet
                         : target == 3 ? path("fuzz-folder")
                         : target == 4 ? QStringLiteral("-")
                                       : out + ".json");
            }
            const QByteArray before = bytesOf(sheet);
            const SafeCliOutcome run = safeCli(args);
            ++cases;
            const QString what =
                args.join(' ') + " -> " + QString::number(run.exitCode) + ": " + run.err.left(300);
            QVERIFY2(run.exitCode >= 0 && run.exitCode <= 2, qPrintable(what));
            if (run.exitCode != 0) {
                QVERIFY2(isSentence(run.err), qPrintable(what));
            } else {
                ++succeeded;
                QVERIFY2(isValidProject(sheet), qPrintable(what));
            }
            // The input is only ever replaced by a valid project (an edit in place).
            if (bytesOf(sheet) != before) {
                QVERIFY2(isValidProject(sheet), qPrintable(what));
            }
            QVERIFY2(isValidProject(sheet), qPrintable(what));
            if (QFileInfo::exists(out + ".devsurf")) {
                QVERIFY2(isValidProject(out + ".devsurf"), qPrintable(what));
                QFile::remove(out + ".devsurf");
            }
        }
        qInfo("%d cases, %d of them valid commands", cases, succeeded);
        QVERIFY(cases >= 2500);
    }
};

DEVSURF_REGISTER_TEST(TstCliSafety);
#include "tst_cli_safety.moc"
