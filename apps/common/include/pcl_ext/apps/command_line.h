/*
 * pcl_ext: command lines in the style of the PCL tools.
 */
#pragma once

#include <chrono>
#include <cstddef>
#include <string>
#include <vector>

namespace pcl_ext {
namespace apps {
/** \brief A PCL-tools command line: `pcl_ext_<verb> input output -option value
 * -switch`.
 *
 * Options are single-dash words bound to variables whose current values are the
 * defaults;
 * `-h` (or `-help`, `--help`) prints the synopsis and every option with its default.
 * Anything not declared is an error, as is a missing or malformed value.
 *
 * \code
 * int k = 50;
 * std::string input, output;
 * pcl_ext::apps::CommandLine cl ("pcl_ext_example", "Estimates something.");
 * cl.addPositional ("input.pcd", input, "input cloud");
 * cl.addPositional ("output.pcd", output, "where to write the result");
 * cl.addOption ("k", k, "number of neighbours");
 * if (const int code = cl.parse (argc, argv); code >= 0)
 *   return code;  // help printed (0) or a usage error reported (1)
 * \endcode
 */
class CommandLine {
public:
  CommandLine (std::string program, std::string description);

  /** \brief A required (or optional) positional argument, in order of declaration. */
  void
  addPositional (const std::string& name,
                 std::string& value,
                 const std::string& help,
                 bool required = true);

  /** \brief One or more positional arguments (e.g. `input...`): those that the
   * positionals declared before and after it leave (one list per command line). */
  void
  addPositionalList (const std::string& name,
                     std::vector<std::string>& values,
                     const std::string& help);

  void
  addOption (const std::string& name, int& value, const std::string& help);
  void
  addOption (const std::string& name, unsigned int& value, const std::string& help);
  void
  addOption (const std::string& name, double& value, const std::string& help);
  void
  addOption (const std::string& name, std::string& value, const std::string& help);

  /** \brief A switch without value: present sets \a value to true. */
  void
  addSwitch (const std::string& name, bool& value, const std::string& help);

  /** \brief Parse; returns -1 to go on, or the exit code to return from main: 0 after
   * -h, 1 after a usage error (reported on stderr with the synopsis). */
  int
  parse (int argc, const char* const* argv);

  /** \brief Print the synopsis and every option with its default, to stdout. */
  void
  printHelp () const;

  /** \brief The options given on the command line as they were written (`-name`, then
   * the value unless a switch), in order, but those named in \a except: to hand the
   * same options to another run of the tool. */
  std::vector<std::string>
  getGivenOptions (const std::vector<std::string>& except = {}) const;

  /** \brief Whether option \a name was given on the command line (after parse()). */
  bool
  given (const std::string& name) const;

private:
  enum class Kind { Int, Unsigned, Double, String, Switch };
  struct Option {
    std::string name;
    Kind kind = Kind::Int;
    void* target = nullptr;
    std::string help;
    std::string default_text;
    bool given = false;
    std::string given_text;
    std::size_t given_order = 0;
  };
  struct Positional {
    std::string name;
    std::string* target;
    std::string help;
    bool required;
    std::vector<std::string>* list = nullptr;
  };

  /** Hands the positional arguments to their targets; false after a usage error. */
  bool
  assignPositionals (const std::vector<std::string>& args);

  static Option
  makeOption (const std::string& name,
              Kind kind,
              void* target,
              const std::string& help,
              const std::string& default_text);
  bool
  assign (Option& option, const std::string& text);
  void
  usageError (const std::string& message) const;
  std::string
  synopsis () const;

  std::string program_;
  std::string description_;
  std::vector<Option> options_;
  std::vector<Positional> positionals_;
};

/** \brief Prints a stage the way PCL tools do: `Computing normals ... [done, 12 ms :
 * 1000 points]`.
 */
class StageTimer {
public:
  /** \brief Prints "<what> " and starts the clock. */
  explicit StageTimer (const std::string& what);

  /** \brief Prints "[done, X ms : N points]" and returns the elapsed milliseconds. */
  double
  done (std::size_t points);

  /** \brief Milliseconds since construction. */
  double
  elapsedMs () const;

private:
  std::chrono::steady_clock::time_point start_;
};
} // namespace apps
} // namespace pcl_ext
