#include "ScattererCommandLine.h"

#include "ScattererRenderOptions.h"

#include <iostream>

namespace scatterer_examples
{
void SetUpCommandLine(CLI::App& app)
{
  const std::string program = app.get_name();
  app.set_help_flag("-h,--help", "this text");
  app.set_version_flag(
    "--version", [program]() { return VersionText(program); },
    "the ScattererTemplate and VTK versions");
  // Wide enough for "--multiple-scattering K"; CLI11 indents continued description lines.
  app.get_formatter()->column_width(28);
}

void ThrowUsageError(const std::string& message)
{
  throw CLI::ValidationError(message);
}

void RequirePngPath(const std::string& option, const std::string& path)
{
  if (path.size() < 5 || path.substr(path.size() - 4) != ".png")
  {
    ThrowUsageError(option + " must name a .png file, got '" + path + "'");
  }
}

void ThrowConflict(const std::string& a, const std::string& b, const std::string& why)
{
  ThrowUsageError(a + " and " + b + " cannot be combined: " + why);
}

CLI::Option* AddValueOption(CLI::App& app, const std::string& name, const std::string& valueName,
  const std::string& description, std::function<void(const std::string&)> set)
{
  // TakeAll keeps every occurrence, so a repeat with another value can be refused;
  // CLI11's default would stop at the second occurrence with a less helpful message.
  const auto take = [name, set](const std::vector<std::string>& values)
  {
    for (const std::string& v : values)
    {
      if (v != values.front())
      {
        ThrowUsageError(name + " given twice with different values ('" + values.front() +
          "' and '" + v + "'); give it once");
      }
    }
    set(values.front());
  };
  return app.add_option_function<std::vector<std::string>>(name, take, description)
    ->type_name(valueName)
    ->expected(1)
    ->allow_extra_args(false)
    ->multi_option_policy(CLI::MultiOptionPolicy::TakeAll);
}

void RejectTogether(const CLI::Option* a, const CLI::Option* b, const std::string& why)
{
  if (a->count() > 0 && b->count() > 0)
  {
    ThrowConflict(a->get_name(), b->get_name(), why);
  }
}

int ParseCommandLine(CLI::App& app, int argc, char* argv[])
{
  const std::string program = app.get_name();
  try
  {
    app.parse(argc, argv);
    return ContinueRun;
  }
  catch (const CLI::CallForHelp&)
  {
    std::cout << app.help();
    return ExitOk;
  }
  catch (const CLI::CallForVersion& e)
  {
    std::cout << e.what();
    return ExitOk;
  }
  catch (const CLI::ParseError& e)
  {
    std::string message = e.what();
    // Every value option takes one value, so CLI11's argument-count error means the
    // value is missing ("--frames: 1 required N missing").
    if (dynamic_cast<const CLI::ArgumentMismatch*>(&e))
    {
      message = "option " + message.substr(0, message.find(':')) + " needs a value";
    }
    else if (dynamic_cast<const CLI::ExtrasError*>(&e) && !app.remaining().empty())
    {
      message.clear();
      for (const std::string& arg : app.remaining())
      {
        message += (message.empty() ? "unknown argument '" : ", '") + arg + "'";
      }
    }
    std::cerr << program << ": " << message << "\n"
              << "Run '" << program << " --help' for the options.\n";
    return ExitUsage;
  }
}
}
