#include "pattern_commands.h"

#include "io/file_error.h"
#include "io/pattern/fabrication_report.h"
#include "io/pattern/page_plan.h"
#include "io/pattern/pattern_writers.h"
#include "io/project_file.h"
#include "model/pattern/cutting_pattern.h"
#include "model/project.h"

#include <QGuiApplication>
#include <QString>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <iostream>
#include <map>
#include <optional>
#include <stdexcept>

namespace devsurf::app {

namespace {

constexpr int kExitOk = 0;

struct PatternArguments {
    std::string file;
    std::map<std::string, std::string> values;
    bool splines = false;
    bool r12 = false;
    bool rulings = false;
    bool json = false;
};

PatternArguments parsePatternArguments(const std::vector<std::string>& args,
                                       const std::vector<std::string>& valued,
                                       const std::vector<std::string>& flags) {
    PatternArguments result;
    std::vector<std::string> positional;
    for (std::size_t i = 0; i < args.size(); ++i) {
        const std::string& arg = args[i];
        if (arg.size() < 2 || arg[0] != '-') {
            positional.push_back(arg);
            continue;
        }
        if (std::find(flags.begin(), flags.end(), arg) != flags.end()) {
            bool& flag = arg == "--splines" ? result.splines
                         : arg == "--r12"   ? result.r12
                         : arg == "--json"  ? result.json
                                            : result.rulings;
            flag = true;
            continue;
        }
        if (std::find(valued.begin(), valued.end(), arg) == valued.end()) {
            throw std::invalid_argument("unknown option '" + arg + "'");
        }
        if (i + 1 >= args.size()) {
            throw std::invalid_argument("option '" + arg + "' needs a value");
        }
        if (!result.values.emplace(arg, args[i + 1]).second) {
            throw std::invalid_argument("option '" + arg + "' is given twice");
        }
        ++i;
    }
    if (positional.size() != 1) {
        throw std::invalid_argument("expected one project file");
    }
    result.file = positional.front();
    return result;
}

double parseMillimetres(const std::string& text, const std::string& option, double low,
                        double high) {
    try {
        std::size_t used = 0;
        const double value = std::stod(text, &used);
        if (used == text.size() && std::isfinite(value) && value >= low && value <= high) {
            return value;
        }
    } catch (const std::exception&) {
    }
    char range[96];
    std::snprintf(range, sizeof range, "between %g and %g mm", low, high);
    throw std::invalid_argument("option '" + option + "' needs a length " + range + ", not '" +
                                text + "'");
}

struct Settings {
    model::PatternOptions pattern;
    io::PatternWriteOptions write;
};

Settings settingsOf(const PatternArguments& args) {
    Settings settings;
    const auto& v = args.values;
    if (v.count("--sheet") != 0 && v.count("--paper") != 0) {
        throw std::invalid_argument("give either --sheet or --paper, not both");
    }
    if (auto it = v.find("--paper"); it != v.end()) {
        const std::optional<io::Paper> paper = io::paperFromName(it->second);
        if (!paper) {
            throw std::invalid_argument("option '--paper' needs A4, A3 or Letter, not '" +
                                        it->second + "'");
        }
        settings.write.paper = *paper;
        // Sheets as large as a page can print: every sheet then prints on one page.
        settings.pattern.sheetSize = io::printableSheet(io::paperSize(*paper));
    }
    if (auto it = v.find("--sheet"); it != v.end()) {
        const std::size_t comma = it->second.find(',');
        if (comma == std::string::npos) {
            throw std::invalid_argument("option '--sheet' needs WIDTH,HEIGHT in mm, not '" +
                                        it->second + "'");
        }
        settings.pattern.sheetSize = {
            parseMillimetres(it->second.substr(0, comma), "--sheet", 1.0, 100000.0),
            parseMillimetres(it->second.substr(comma + 1), "--sheet", 1.0, 100000.0)};
    }
    if (auto it = v.find("--tolerance"); it != v.end()) {
        settings.pattern.tolerance = parseMillimetres(it->second, "--tolerance", 1e-4, 10.0);
        settings.write.tolerance = settings.pattern.tolerance;
    }
    if (auto it = v.find("--seam"); it != v.end()) {
        settings.pattern.seamAllowance = parseMillimetres(it->second, "--seam", 0.0, 1000.0);
    }
    settings.pattern.rulings = args.rulings;
    settings.write.splines = args.splines;
    settings.write.r12 = args.r12;
    return settings;
}

model::CuttingPattern patternOf(const std::string& file, const Settings& settings) {
    const model::Project project = io::loadProjectFile(QString::fromStdString(file));
    model::CuttingPattern pattern = model::buildCuttingPattern(project, settings.pattern);
    if (pattern.pieces.empty()) {
        std::string why = pattern.problems.empty() ? "it has no surface" : pattern.problems.front();
        if (!why.empty() && why.back() == '.') {
            why.pop_back();
        }
        throw io::FileError("'" + file + "' has no cutting pattern: " + why + ".");
    }
    return pattern;
}

} // namespace

int runExportPatternCommand(const std::vector<std::string>& rawArgs) {
    const PatternArguments args = parsePatternArguments(
        rawArgs, {"-o", "--format", "--sheet", "--paper", "--tolerance", "--seam"},
        {"--splines", "--r12", "--rulings"});
    auto output = args.values.find("-o");
    if (output == args.values.end()) {
        throw std::invalid_argument("the output file is missing (use -o FILE)");
    }
    std::optional<io::PatternFormat> format;
    if (auto it = args.values.find("--format"); it != args.values.end()) {
        format = io::patternFormatFromName(it->second);
        if (!format) {
            throw std::invalid_argument("option '--format' needs dxf, svg, pdf or fold, not '" +
                                        it->second + "'");
        }
    } else {
        const std::string& out = output->second;
        const std::size_t dot = out.rfind('.');
        format = dot == std::string::npos ? std::nullopt
                                          : io::patternFormatFromName(out.substr(dot + 1));
        if (!format) {
            throw std::invalid_argument("the format is missing (use --format dxf|svg|pdf|fold)");
        }
    }
    Settings settings = settingsOf(args);
    if (*format == io::PatternFormat::Fold) {
        // A folding simulator bends the pieces along the rulings (flat "F" edges).
        settings.pattern.rulings = true;
    }
    if (settings.write.r12 && *format != io::PatternFormat::Dxf) {
        throw std::invalid_argument("option '--r12' is for DXF only");
    }
    if (settings.write.splines && *format != io::PatternFormat::Dxf) {
        throw std::invalid_argument("option '--splines' is for DXF only");
    }
    const model::CuttingPattern pattern = patternOf(args.file, settings);
    for (const std::string& problem : pattern.problems) {
        std::cerr << "devsurf-cli: warning: " << problem << "\n";
    }
    if (settings.write.splines && settings.write.r12) {
        std::cerr << "devsurf-cli: warning: DXF R12 has no splines; curves are written as "
                     "polylines.\n";
    }
    io::savePatternFile(pattern, *format, QString::fromStdString(output->second), settings.write);
    std::cout << "Wrote " << output->second << " (" << io::patternFormatName(*format) << ", "
              << pattern.pieces.size() << (pattern.pieces.size() == 1 ? " piece" : " pieces")
              << " on " << pattern.sheetCount << (pattern.sheetCount == 1 ? " sheet" : " sheets")
              << ")\n";
    return kExitOk;
}

int runReportCommand(const std::vector<std::string>& rawArgs) {
    const PatternArguments args = parsePatternArguments(
        rawArgs, {"--sheet", "--paper", "--tolerance", "--seam"}, {"--json", "--rulings"});
    const Settings settings = settingsOf(args);
    const model::CuttingPattern pattern = patternOf(args.file, settings);
    const io::FabricationReport report = io::fabricationReport(pattern);
    if (args.json) {
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
    if (argc > 1 && std::strcmp(argv[1], "export") == 0) {
        if (qEnvironmentVariableIsEmpty("QT_QPA_PLATFORM")) {
            qputenv("QT_QPA_PLATFORM", "offscreen");
        }
        g_defaultHandler = qInstallMessageHandler(quietHandler);
        return std::make_unique<QGuiApplication>(argc, argv);
    }
    return std::make_unique<QCoreApplication>(argc, argv);
}

} // namespace devsurf::app
