#include "pattern_commands.h"
#include "problem_text.h"
#include "shape_commands.h"

#include "cli_output.h"

#include "io/file_error.h"
#include "io/pattern/fabrication_report.h"
#include "io/pattern/page_plan.h"
#include "io/pattern/pattern_writers.h"
#include "io/project_file.h"
#include "model/pattern/cutting_pattern.h"
#include "model/pattern/sampling_bound.h"
#include "model/project.h"

#include <QFileInfo>
#include <QGuiApplication>
#include <QString>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <iostream>
#include <optional>
#include <stdexcept>

namespace devsurf::app {

namespace {

struct Settings {
    model::PatternOptions pattern;
    io::PatternWriteOptions write;
};

Settings settingsOf(const SubcommandArguments& args) {
    Settings settings;
    const std::optional<std::string> paperText = args.value("paper");
    const std::optional<std::string> sheetText = args.value("sheet");
    if (paperText && sheetText) {
        throw UsageError{"give either --sheet or --paper, not both"};
    }
    if (paperText) {
        const std::optional<io::Paper> paper = io::paperFromName(*paperText);
        if (!paper) {
            throw UsageError{"option '--paper' needs A4, A3 or Letter, not '" + *paperText + "'"};
        }
        settings.write.paper = *paper;
        // Sheets as large as a page can print: every sheet then prints on one page.
        settings.pattern.sheetSize = io::printableSheet(io::paperSize(*paper));
    }
    if (sheetText) {
        const std::size_t comma = sheetText->find(',');
        if (comma == std::string::npos) {
            throw UsageError{"option '--sheet' needs WIDTH,HEIGHT in mm, not '" + *sheetText + "'"};
        }
        settings.pattern.sheetSize = {
            parseReal(sheetText->substr(0, comma), "--sheet", 1.0, 100000.0, "a length in mm"),
            parseReal(sheetText->substr(comma + 1), "--sheet", 1.0, 100000.0, "a length in mm")};
    }
    if (const std::optional<std::string> text = args.value("tolerance")) {
        settings.pattern.tolerance = parseReal(*text, "--tolerance", 1e-4, 10.0, "a length in mm");
        settings.write.tolerance = settings.pattern.tolerance;
    }
    if (const std::optional<std::string> text = args.value("seam")) {
        settings.pattern.seamAllowance = parseReal(*text, "--seam", 0.0, 1000.0, "a length in mm");
    }
    settings.pattern.rulings = args.isSet("rulings");
    settings.write.splines = args.isSet("splines");
    settings.write.r12 = args.isSet("r12");
    return settings;
}

// A design whose curves would need more samples than model::pattern::kMaxCurveSamples at the
// tolerance (far-away geometry took 9 s and more) is refused at once, with a tolerance that
// would do.
void refuseUnboundedSampling(const model::Project& project, const std::string& file,
                             double tolerance) {
    const std::optional<model::pattern::OversampledSurface> over =
        model::pattern::oversampledSurface(project, tolerance);
    if (!over) {
        return;
    }
    std::string advice = " No tolerance up to 10 mm is coarse enough.";
    if (over->coarser > 0.0) {
        char text[96];
        std::snprintf(text, sizeof text, " Give --tolerance %g (mm) to write it.", over->coarser);
        advice = text;
    }
    char line[320];
    std::snprintf(line, sizeof line,
                  "'%s' is too large for the tolerance %g mm: surface %d reaches %.0f mm "
                  "from the origin, and its curves would need %ld samples, which would take "
                  "minutes.",
                  file.c_str(), tolerance, over->surface + 1, over->reach, over->samples);
    throw io::FileError(line + advice);
}

model::CuttingPattern patternOf(const std::string& file, const Settings& settings) {
    const model::Project project = io::loadProjectFile(QString::fromStdString(file));
    refuseUnboundedSampling(project, file, settings.pattern.tolerance);
    model::CuttingPattern pattern = model::buildCuttingPattern(project, settings.pattern);
    if (pattern.pieces.empty()) {
        const std::string why =
            pattern.problems.empty()
                ? "it has no surface"
                : withoutFinalPeriod(
                      ProblemText::of(pattern.problems.front(), pattern).toStdString());
        throw io::FileError("'" + file + "' has no cutting pattern: " + why + ".");
    }
    return pattern;
}

} // namespace

int runExportPatternCommand(const SubcommandArguments& args) {
    const std::string file = args.onePositional("one project file");
    const std::string output = args.required("o", "the output file is missing (use -o FILE)");
    std::optional<io::PatternFormat> format;
    const std::string suffix =
        QFileInfo(QString::fromStdString(output)).suffix().toLower().toStdString();
    // The 3D shape formats share the subcommand.
    const std::optional<std::string> formatOption = args.value("format");
    const std::string shapeFormat = formatOption ? *formatOption : suffix;
    if (isShapeFormat(shapeFormat)) {
        return runExportShapeCommand(args, shapeFormat);
    }
    if (args.isSet("thickness")) {
        throw UsageError{"option '--thickness' is for meshes (obj, stl, ply) only"};
    }
    if (const std::optional<std::string> name = args.value("format")) {
        format = io::patternFormatFromName(*name);
        if (!format) {
            throw UsageError{"option '--format' needs dxf, svg, pdf, fold, step, step214, iges, "
                             "obj, stl or ply, not '" +
                             *name + "'"};
        }
    } else {
        format = io::patternFormatFromName(suffix);
        if (!format) {
            throw UsageError{"the format is missing (use --format dxf|svg|pdf|fold|step|iges|obj|"
                             "stl|ply)"};
        }
    }
    const std::string formatName = io::patternFormatName(*format);
    std::string upper = formatName;
    std::transform(upper.begin(), upper.end(), upper.begin(),
                   [](unsigned char c) { return static_cast<char>(std::toupper(c)); });
    checkOutput(output, {file}, OutputKind::Other, "the " + upper + " pattern");
    checkExtension(output, formatName, upper);
    Settings settings = settingsOf(args);
    if (*format == io::PatternFormat::Fold) {
        // A folding simulator bends the pieces along the rulings (flat "F" edges).
        settings.pattern.rulings = true;
    }
    if (settings.write.r12 && *format != io::PatternFormat::Dxf) {
        throw UsageError{"option '--r12' is for DXF only"};
    }
    if (settings.write.splines && *format != io::PatternFormat::Dxf) {
        throw UsageError{"option '--splines' is for DXF only"};
    }
    if (output == "-" && *format == io::PatternFormat::Pdf) {
        throw UsageError{"a PDF is written to a file, not to standard output ('-')"};
    }
    const model::CuttingPattern pattern = patternOf(file, settings);
    settings.write.problemTexts = patternProblemTexts(pattern);
    for (const std::string& problem : settings.write.problemTexts) {
        std::cerr << "devsurf-cli: warning: " << problem << "\n";
    }
    if (settings.write.splines && settings.write.r12) {
        std::cerr << "devsurf-cli: warning: DXF R12 has no splines; curves are written as "
                     "polylines.\n";
    }
    if (output == "-") {
        writeStandardOutput(
            *format == io::PatternFormat::Dxf   ? io::patternDxf(pattern, settings.write)
            : *format == io::PatternFormat::Svg ? io::patternSvg(pattern, settings.write)
                                                : io::patternFold(pattern, settings.write));
        return kExitOk;
    }
    io::savePatternFile(pattern, *format, QString::fromStdString(output), settings.write);
    std::cout << "Wrote " << output << " (" << formatName << ", " << pattern.pieces.size()
              << (pattern.pieces.size() == 1 ? " piece" : " pieces") << " on " << pattern.sheetCount
              << (pattern.sheetCount == 1 ? " sheet" : " sheets") << ")\n";
    return kExitOk;
}

int runReportCommand(const SubcommandArguments& args) {
    const std::string file = args.onePositional("one project file");
    const Settings settings = settingsOf(args);
    const model::CuttingPattern pattern = patternOf(file, settings);
    const io::FabricationReport report =
        io::fabricationReport(pattern, patternProblemTexts(pattern));
    if (args.isSet("json")) {
        std::cout << io::fabricationReportJson(report).toStdString();
    } else {
        std::cout << io::fabricationReportText(report);
    }
    return kExitOk;
}

namespace {

QtMessageHandler g_defaultHandler = nullptr;

// The GUI platform's notes about the session (no runtime folder when run as a service) are no
// concern of a command-line user: stderr keeps its one sentence per problem.
void quietHandler(QtMsgType type, const QMessageLogContext& context, const QString& message) {
    if (type != QtFatalMsg && message.startsWith(QLatin1String("QStandardPaths:"))) {
        return;
    }
    g_defaultHandler(type, context, message);
}

} // namespace

std::unique_ptr<QCoreApplication> makeCliApplication(int& argc, char** argv) {
    // The pattern's writers paint text; SVG curves (import-curves, sheet --outline) are read
    // by Qt's SVG renderer: both need a QGuiApplication, offscreen.
    const bool painting = argc > 1 && (std::strcmp(argv[1], "export") == 0 ||
                                       std::strcmp(argv[1], "import-curves") == 0 ||
                                       std::strcmp(argv[1], "sheet") == 0);
    if (painting) {
        if (qEnvironmentVariableIsEmpty("QT_QPA_PLATFORM")) {
            qputenv("QT_QPA_PLATFORM", "offscreen");
        }
        g_defaultHandler = qInstallMessageHandler(quietHandler);
        return std::make_unique<QGuiApplication>(argc, argv);
    }
    return std::make_unique<QCoreApplication>(argc, argv);
}

} // namespace devsurf::app
