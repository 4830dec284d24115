// The command line of every example program, run the same way: CLI11 parses, and
// every mistake ends in one line "<program>: <what and why>", the pointer to --help
// and exit status 2; --help and --version print to stdout and exit 0.
//
// Why CLI11 (Debian: libcli11-dev) and not vtksys::CommandLineArguments: it is
// maintained, takes both --opt value and --opt=value, and gives repeated-option
// detection, option groups, a help text generated from the same definitions the
// parser uses (the help cannot drift from the options), and errors as exceptions that
// one place maps to our messages. vtksys' parser has none of the last four.
#ifndef ScattererCommandLine_h
#define ScattererCommandLine_h

#include <CLI/CLI.hpp>

#include <functional>
#include <string>

namespace scatterer_examples
{
/** Exit statuses of the example programs (their --help and README.md list them). */
enum ExitStatus
{
  ExitOk = 0,
  ExitFailure = 1, // input unreadable or refused, rendering failed, output not written
  ExitUsage = 2,   // bad command line
  ExitSkipped = 77 // scatterer-viewer --test without the prepared CT head (CTest: skipped)
};

/** What ParseCommandLine returns when the program should go on. */
constexpr int ContinueRun = -1;

/**
 * Sets up @p app (named after the program) with -h/--help, --version (VersionText)
 * and the help layout the programs share.
 */
void SetUpCommandLine(CLI::App& app);

/**
 * Adds "--name VALUE" (also "--name=VALUE"). @p set parses and stores the value and
 * calls ThrowUsageError when it is bad. Given twice with the same value is fine;
 * with different values it is refused, naming both (no silent "last one wins").
 */
CLI::Option* AddValueOption(CLI::App& app, const std::string& name, const std::string& valueName,
  const std::string& description, std::function<void(const std::string&)> set);

/** Ends parsing with a usage error: "<program>: @p message", exit status 2. */
[[noreturn]] void ThrowUsageError(const std::string& message);

/** ThrowUsageError unless @p path names a .png file (the PNG writers write PNG whatever
 * the name says): "@p option must name a .png file". */
void RequirePngPath(const std::string& option, const std::string& path);

/** A usage error for two options that contradict each other: "A and B cannot be combined: why". */
[[noreturn]] void ThrowConflict(const std::string& a, const std::string& b, const std::string& why);

/** ThrowConflict when @p a and @p b were both given. */
void RejectTogether(const CLI::Option* a, const CLI::Option* b, const std::string& why);

/**
 * Parses argv. Returns ContinueRun, or the exit status once --help or --version
 * (ExitOk) or a usage error (ExitUsage) has been printed.
 */
int ParseCommandLine(CLI::App& app, int argc, char* argv[]);
}

#endif
