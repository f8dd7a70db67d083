#pragma once

// How devsurf-cli reads its arguments: one QCommandLineParser per subcommand, and the number
// and id parsers every subcommand shares. Bad usage throws UsageError (exit code 1) with a
// message without a final period.

#include "model/ids.h"
#include "model/project.h"

#include <QCommandLineParser>

#include <cstdint>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

namespace devsurf::app {

// devsurf-cli's exit codes: done; bad usage; an input that cannot do what was asked.
inline constexpr int kExitOk = 0;
inline constexpr int kExitUsage = 1;
inline constexpr int kExitInput = 2;

// The message of a subcommand that writes a file and was given no -o.
inline constexpr const char* kMissingOutput = "the output file is missing (use -o FILE)";

struct UsageError {
    std::string message;
};

// The input cannot do what was asked (no such vertex, the solver stopped): exit 1 with the
// sentence, nothing written.
struct InputError : std::runtime_error {
    using std::runtime_error::runtime_error;
};

// One option of a subcommand: its name ("o" is -o, longer names are --name), the name of its
// value (empty for a flag) and one line of help.
struct OptionSpec {
    const char* name;
    const char* valueName;
    const char* help;
};

// A subcommand as its --help shows it.
struct SubcommandSpec {
    const char* name;
    const char* synopsis;    // after "devsurf-cli "
    const char* description; // lines of the overall help, indented
    std::vector<OptionSpec> options;
};

// The parsed arguments of one subcommand.
class SubcommandArguments {
public:
    // Throws UsageError for an unknown option, a missing value or a valued option given twice.
    SubcommandArguments(const SubcommandSpec& spec, const std::vector<std::string>& args);

    // --help or -h was given: the caller prints help() and exits 0.
    bool helpRequested() const { return m_parser.isSet(QStringLiteral("help")); }
    std::string help() const;

    // False also for an option the subcommand does not have (report has no --splines).
    bool isSet(const char* name) const;
    std::optional<std::string> value(const char* name) const;
    // The value, or UsageError(missing) when the option is absent or empty.
    std::string required(const char* name, const std::string& missing) const;
    // The one positional argument (UsageError "expected WHAT" otherwise).
    std::string onePositional(const char* what) const;
    std::size_t positionalCount() const;
    // Exactly `count` positional arguments (UsageError "expected WHAT" otherwise).
    std::vector<std::string> positionals(std::size_t count, const char* what) const;

private:
    bool defines(const char* name) const;

    const SubcommandSpec& m_spec;
    QCommandLineParser m_parser;
};

// "--name" or "-o": how an option is written on the command line.
std::string optionText(const char* name);

// A whole number in [low, high] (UsageError naming the option otherwise).
long parseWhole(const std::string& text, const std::string& option, long low, long high);
// A finite number in [low, high]; `what` completes "needs …" ("a length in mm").
double parseReal(const std::string& text, const std::string& option, double low, double high,
                 const char* what = "a number");
// Exactly `count` finite numbers separated by commas; `example` shows the form ("0,0,100").
std::vector<double> parseReals(const std::string& text, const std::string& option,
                               std::size_t count, const char* example);
// Ids such as "0,4,7", each once; `what` names them ("vertex", "edge").
std::vector<std::uint32_t> parseIds(const std::string& text, const std::string& option,
                                    const char* what);
// The 0-based index of surface number `surface` (1-based; 0 means the first). UsageError if
// the project has no such surface; `purpose` completes "the project has no surface to …".
std::size_t surfaceIndex(int surface, const model::Project& project, const std::string& purpose);

} // namespace devsurf::app
