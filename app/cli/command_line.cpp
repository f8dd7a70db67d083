#include "command_line.h"
#include "problem_text.h"

#include <QStringList>

#include <charconv>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <set>

namespace devsurf::app {

namespace {

// The comma-separated items of text; UsageError for an empty item ("0,,4", "0,4,").
std::vector<std::string> items(const std::string& text, const std::string& option,
                               const std::string& needs) {
    std::vector<std::string> result;
    std::size_t start = 0;
    for (;;) {
        const std::size_t comma = text.find(',', start);
        result.push_back(text.substr(start, comma == std::string::npos ? comma : comma - start));
        if (result.back().empty()) {
            throw UsageError{"option '" + option + "' needs " + needs + ", not '" + text + "'"};
        }
        if (comma == std::string::npos) {
            return result;
        }
        start = comma + 1;
    }
}

// std::from_chars: no leading spaces, no '+', no hexadecimal, the whole text or nothing.
template <typename T> bool parseAll(const std::string& text, T& value) {
    const char* end = text.data() + text.size();
    const auto [used, error] = std::from_chars(text.data(), end, value);
    return error == std::errc() && used == end;
}

} // namespace

std::string optionText(const char* name) {
    return std::string(name[1] == '\0' ? "-" : "--") + name;
}

SubcommandArguments::SubcommandArguments(const SubcommandSpec& spec,
                                         const std::vector<std::string>& args)
    : m_spec(spec) {
    m_parser.setSingleDashWordOptionMode(QCommandLineParser::ParseAsLongOptions);
    m_parser.addOption(QCommandLineOption({QStringLiteral("h"), QStringLiteral("help")},
                                          QStringLiteral("Show this help.")));
    for (const OptionSpec& option : spec.options) {
        m_parser.addOption(QCommandLineOption(QString::fromLatin1(option.name),
                                              QString::fromUtf8(option.help),
                                              QString::fromLatin1(option.valueName)));
    }
    QStringList arguments{QStringLiteral("devsurf-cli")};
    for (const std::string& arg : args) {
        arguments << QString::fromStdString(arg);
    }
    if (!m_parser.parse(arguments)) {
        const QStringList unknown = m_parser.unknownOptionNames();
        if (!unknown.isEmpty()) {
            const QString name = unknown.front();
            throw UsageError{"unknown option '" + std::string(name.size() == 1 ? "-" : "--") +
                             name.toStdString() + "'"};
        }
        std::string error = withoutFinalPeriod(m_parser.errorText().toStdString());
        if (!error.empty()) {
            error[0] = static_cast<char>(std::tolower(static_cast<unsigned char>(error[0])));
        }
        throw UsageError{error};
    }
    for (const OptionSpec& option : spec.options) {
        if (option.valueName[0] != '\0' &&
            m_parser.values(QString::fromLatin1(option.name)).size() > 1) {
            throw UsageError{"option '" + optionText(option.name) + "' is given twice"};
        }
    }
}

std::string SubcommandArguments::help() const {
    // Qt's list of options, after our own usage line (Qt's names the program as started).
    const QString qtHelp = m_parser.helpText();
    const qsizetype options = qtHelp.indexOf(QStringLiteral("Options:"));
    return std::string("Usage: devsurf-cli ") + m_spec.synopsis + "\n\n" + m_spec.description +
           "\n\n" + (options < 0 ? QString() : qtHelp.mid(options)).toStdString();
}

bool SubcommandArguments::defines(const char* name) const {
    for (const OptionSpec& option : m_spec.options) {
        if (std::strcmp(option.name, name) == 0) {
            return true;
        }
    }
    return false;
}

bool SubcommandArguments::isSet(const char* name) const {
    return defines(name) && m_parser.isSet(QString::fromLatin1(name));
}

std::optional<std::string> SubcommandArguments::value(const char* name) const {
    const QString key = QString::fromLatin1(name);
    if (!isSet(name)) {
        return std::nullopt;
    }
    return m_parser.value(key).toStdString();
}

std::string SubcommandArguments::required(const char* name, const std::string& missing) const {
    const std::optional<std::string> text = value(name);
    if (!text || text->empty()) {
        throw UsageError{missing};
    }
    return *text;
}

std::size_t SubcommandArguments::positionalCount() const {
    return static_cast<std::size_t>(m_parser.positionalArguments().size());
}

std::string SubcommandArguments::onePositional(const char* what) const {
    const QStringList positional = m_parser.positionalArguments();
    if (positional.size() != 1) {
        throw UsageError{std::string("expected ") + what};
    }
    return positional.front().toStdString();
}

std::vector<std::string> SubcommandArguments::positionals(std::size_t count,
                                                          const char* what) const {
    const QStringList positional = m_parser.positionalArguments();
    if (static_cast<std::size_t>(positional.size()) != count) {
        throw UsageError{std::string("expected ") + what};
    }
    std::vector<std::string> result;
    for (const QString& text : positional) {
        result.push_back(text.toStdString());
    }
    return result;
}

long parseWhole(const std::string& text, const std::string& option, long low, long high) {
    long value = 0;
    if (!parseAll(text, value) || value < low || value > high) {
        throw UsageError{"option '" + option + "' needs a whole number between " +
                         std::to_string(low) + " and " + std::to_string(high) + ", not '" + text +
                         "'"};
    }
    return value;
}

double parseReal(const std::string& text, const std::string& option, double low, double high,
                 const char* what) {
    double value = 0.0;
    if (!parseAll(text, value) || !std::isfinite(value) || value < low || value > high) {
        char range[96];
        std::snprintf(range, sizeof range, " between %g and %g", low, high);
        throw UsageError{"option '" + option + "' needs " + what + range + ", not '" + text + "'"};
    }
    return value;
}

std::vector<double> parseReals(const std::string& text, const std::string& option,
                               std::size_t count, const char* example) {
    const std::string needs = std::to_string(count) + " numbers such as " + example;
    std::vector<double> values;
    for (const std::string& item : items(text, option, needs)) {
        double value = 0.0;
        if (!parseAll(item, value) || !std::isfinite(value)) {
            throw UsageError{"option '" + option + "' needs " + needs + ", not '" + text + "'"};
        }
        values.push_back(value);
    }
    if (values.size() != count) {
        throw UsageError{"option '" + option + "' needs " + needs + ", not '" + text + "'"};
    }
    return values;
}

std::vector<std::uint32_t> parseIds(const std::string& text, const std::string& option,
                                    const char* what) {
    const std::string needs = std::string(what) + " ids such as 0,4,7";
    std::vector<std::uint32_t> ids;
    std::set<std::uint32_t> seen;
    for (const std::string& item : items(text, option, needs)) {
        std::uint32_t id = 0;
        if (!parseAll(item, id) || id == 0xffffffffu) {
            throw UsageError{"option '" + option + "' needs " + needs + ", not '" + text + "'"};
        }
        if (!seen.insert(id).second) {
            throw UsageError{"option '" + option + "' names " + what + " " + item + " twice"};
        }
        ids.push_back(id);
    }
    return ids;
}

std::size_t surfaceIndex(int surface, const model::Project& project, const std::string& purpose) {
    if (project.surfaces.empty()) {
        throw UsageError{"the project has no surface to " + purpose};
    }
    if (surface < 0 || static_cast<std::size_t>(surface) > project.surfaces.size()) {
        throw UsageError{"option '--surface' needs a surface number from 1 to " +
                         std::to_string(project.surfaces.size()) + ", not '" +
                         std::to_string(surface) + "'"};
    }
    return surface == 0 ? 0 : static_cast<std::size_t>(surface - 1);
}

} // namespace devsurf::app
