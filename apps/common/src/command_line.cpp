/*
 * pcl_ext: command lines in the style of the PCL tools.
 */
#include <pcl_ext/apps/command_line.h>

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <climits>
#include <cmath>
#include <cstdlib>
#include <iomanip>
#include <iostream>
#include <sstream>

namespace pcl_ext {
namespace apps {
namespace {
template <typename T>
std::string
toText (const T& value)
{
  std::ostringstream s;
  s << value;
  return s.str();
}
} // namespace

CommandLine::CommandLine (std::string program, std::string description)
: program_ (std::move (program)), description_ (std::move (description))
{}

void
CommandLine::addPositional (const std::string& name,
                            std::string& value,
                            const std::string& help,
                            bool required)
{
  positionals_.push_back ({name, &value, help, required});
}

void
CommandLine::addPositionalList (const std::string& name,
                                std::vector<std::string>& values,
                                const std::string& help)
{
  positionals_.push_back ({name, nullptr, help, true, &values});
}

CommandLine::Option
CommandLine::makeOption (const std::string& name,
                         Kind kind,
                         void* target,
                         const std::string& help,
                         const std::string& default_text)
{
  Option o;
  o.name = name;
  o.kind = kind;
  o.target = target;
  o.help = help;
  o.default_text = default_text;
  return o;
}

void
CommandLine::addOption (const std::string& name, int& value, const std::string& help)
{
  options_.push_back (makeOption (name, Kind::Int, &value, help, toText (value)));
}

void
CommandLine::addOption (const std::string& name,
                        unsigned int& value,
                        const std::string& help)
{
  options_.push_back (makeOption (name, Kind::Unsigned, &value, help, toText (value)));
}

void
CommandLine::addOption (const std::string& name, double& value, const std::string& help)
{
  options_.push_back (makeOption (name, Kind::Double, &value, help, toText (value)));
}

void
CommandLine::addOption (const std::string& name,
                        std::string& value,
                        const std::string& help)
{
  options_.push_back (
      makeOption (name, Kind::String, &value, help, value.empty() ? "none" : value));
}

void
CommandLine::addSwitch (const std::string& name, bool& value, const std::string& help)
{
  options_.push_back (
      makeOption (name, Kind::Switch, &value, help, value ? "on" : "off"));
}

bool
CommandLine::assign (Option& option, const std::string& text)
{
  errno = 0;
  char* end = nullptr;
  switch (option.kind) {
  case Kind::Int: {
    const long v = std::strtol (text.c_str(), &end, 10);
    if (text.empty() || *end != '\0' || errno != 0 || v < INT32_MIN || v > INT32_MAX)
      return false;
    *static_cast<int*> (option.target) = static_cast<int> (v);
    return true;
  }
  case Kind::Unsigned: {
    if (!text.empty() && text[0] == '-')
      return false;
    const unsigned long v = std::strtoul (text.c_str(), &end, 10);
    if (text.empty() || *end != '\0' || errno != 0 || v > UINT32_MAX)
      return false;
    *static_cast<unsigned int*> (option.target) = static_cast<unsigned int> (v);
    return true;
  }
  case Kind::Double: {
    const double v = std::strtod (text.c_str(), &end);
    // NaN and Inf are never meaningful parameters: refuse them here, once for every
    // tool.
    if (text.empty() || *end != '\0' || errno == ERANGE || !std::isfinite (v))
      return false;
    *static_cast<double*> (option.target) = v;
    return true;
  }
  case Kind::String:
    *static_cast<std::string*> (option.target) = text;
    return true;
  case Kind::Switch:
    *static_cast<bool*> (option.target) = true;
    return true;
  }
  return false;
}

int
CommandLine::parse (int argc, const char* const* argv)
{
  std::vector<std::string> args;
  for (int i = 1; i < argc; ++i) {
    const std::string arg = argv[i];
    if (arg == "-h" || arg == "-help" || arg == "--help") {
      printHelp();
      return 0;
    }
    if (arg == "-version" || arg == "--version") {
      std::cout << program_ << " (pcl_ext) " << PCL_EXT_VERSION << std::endl;
      return 0;
    }
    // A dash followed by a letter is an option; "-1.5" is a (negative) value.
    const bool is_option =
        arg.size() > 1 && arg[0] == '-' &&
        (std::isalpha (static_cast<unsigned char> (arg[1])) || arg[1] == '-');
    if (!is_option) {
      args.push_back (arg);
      continue;
    }
    const std::string name = arg.substr (arg.find_first_not_of ('-'));
    Option* option = nullptr;
    for (auto& o : options_)
      if (o.name == name)
        option = &o;
    if (!option) {
      usageError ("unknown option '" + arg + "'");
      return 1;
    }
    if (option->given) {
      usageError ("option '" + arg + "' given twice");
      return 1;
    }
    option->given = true;
    option->given_order = static_cast<std::size_t> (i);
    if (option->kind == Kind::Switch) {
      assign (*option, "");
      continue;
    }
    if (i + 1 >= argc) {
      usageError ("option '" + arg + "' needs a value");
      return 1;
    }
    const std::string value = argv[++i];
    option->given_text = value;
    if (!assign (*option, value)) {
      usageError ("invalid value '" + value + "' for option '" + arg + "'");
      return 1;
    }
  }
  return assignPositionals (args) ? -1 : 1;
}

bool
CommandLine::assignPositionals (const std::vector<std::string>& args)
{
  std::size_t list = positionals_.size();
  for (std::size_t p = 0; p < positionals_.size(); ++p)
    if (positionals_[p].list)
      list = p;
  if (list == positionals_.size()) {
    if (args.size() > positionals_.size()) {
      usageError ("unexpected argument '" + args[positionals_.size()] + "'");
      return false;
    }
    for (std::size_t a = 0; a < args.size(); ++a)
      *positionals_[a].target = args[a];
    for (std::size_t p = args.size(); p < positionals_.size(); ++p)
      if (positionals_[p].required) {
        usageError ("missing argument " + positionals_[p].name);
        return false;
      }
    return true;
  }
  // With a list every positional is required: those before it, those after it, and at
  // least one for the list.
  const std::size_t after = positionals_.size() - list - 1;
  if (args.size() < positionals_.size()) {
    usageError ("missing argument " +
                positionals_[std::min (args.size(), positionals_.size() - 1)].name);
    return false;
  }
  for (std::size_t p = 0; p < list; ++p)
    *positionals_[p].target = args[p];
  positionals_[list].list->assign (args.begin() + list, args.end() - after);
  for (std::size_t p = 0; p < after; ++p)
    *positionals_[list + 1 + p].target = args[args.size() - after + p];
  return true;
}

std::vector<std::string>
CommandLine::getGivenOptions (const std::vector<std::string>& except) const
{
  std::vector<const Option*> given;
  for (const auto& o : options_)
    if (o.given && std::find (except.begin(), except.end(), o.name) == except.end())
      given.push_back (&o);
  std::sort (given.begin(), given.end(), [] (const Option* a, const Option* b) {
    return a->given_order < b->given_order;
  });
  std::vector<std::string> args;
  for (const Option* o : given) {
    args.push_back ("-" + o->name);
    if (o->kind != Kind::Switch)
      args.push_back (o->given_text);
  }
  return args;
}

bool
CommandLine::given (const std::string& name) const
{
  for (const auto& o : options_)
    if (o.name == name)
      return o.given;
  return false;
}

std::string
CommandLine::synopsis() const
{
  std::string s = program_;
  for (const auto& p : positionals_)
    s += p.list       ? " " + p.name + "..."
         : p.required ? " " + p.name
                      : " [" + p.name + "]";
  if (!options_.empty())
    s += " <options>";
  return s;
}

void
CommandLine::usageError (const std::string& message) const
{
  std::cerr << program_ << ": error: " << message << "\n"
            << "Syntax is: " << synopsis() << "\n"
            << "Run '" << program_ << " -h' for the options.\n";
}

void
CommandLine::printHelp() const
{
  std::cout << description_ << "\n\nSyntax is: " << synopsis() << "\n";
  if (!positionals_.empty()) {
    std::cout << "\nArguments:\n";
    for (const auto& p : positionals_)
      std::cout << "  " << std::left << std::setw (25) << p.name << " " << p.help
                << "\n";
  }
  std::cout << "\nOptions:\n";
  for (const auto& o : options_) {
    std::string lhs = "-" + o.name;
    if (o.kind != Kind::Switch)
      lhs += " X";
    std::cout << "  " << std::left << std::setw (25) << lhs << " " << o.help
              << " (default: " << o.default_text << ")\n";
  }
  std::cout << "  " << std::left << std::setw (26) << "-h"
            << "print this help and exit\n";
  std::cout << "  " << std::left << std::setw (26) << "--version"
            << "print the version of pcl_ext and exit\n";
}

StageTimer::StageTimer (const std::string& what)
: start_ (std::chrono::steady_clock::now())
{
  std::cout << what << " " << std::flush;
}

double
StageTimer::elapsedMs() const
{
  return std::chrono::duration<double, std::milli> (std::chrono::steady_clock::now() -
                                                    start_)
      .count();
}

double
StageTimer::done (std::size_t points)
{
  const double ms = elapsedMs();
  std::cout << "[done, " << std::fixed << std::setprecision (0) << ms
            << " ms : " << points << " points]" << std::endl;
  std::cout.unsetf (std::ios::floatfield);
  return ms;
}
} // namespace apps
} // namespace pcl_ext
