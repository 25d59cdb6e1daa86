#include "cli/command_suggestion.hpp"

#include <CLI/CLI.hpp>
#include <algorithm>
#include <numeric>

#include "core/edit_distance.hpp"

namespace rollnoise::cli {

std::string unknown_command_message(const std::string& given,
                                    const std::vector<std::string>& commands) {
  std::string msg = "unknown command '" + given + "'";
  if (const std::string best = nearest_word(given, commands); !best.empty())
    msg += "; did you mean '" + best + "'?";
  msg += "\n  commands:";
  for (const auto& c : commands) msg += " " + c;
  return msg + "\n  (rollnoise --help for all, rollnoise COMMAND --help for one)";
}

std::string check_command(const CLI::App& app, int argc, char** argv) {
  if (argc < 2 || argv[1][0] == '-') return "";
  std::vector<std::string> names;
  for (const CLI::App* sub : app.get_subcommands([](const CLI::App*) { return true; }))
    names.push_back(sub->get_name());
  if (std::find(names.begin(), names.end(), argv[1]) != names.end()) return "";
  return unknown_command_message(argv[1], names);
}

}  // namespace rollnoise::cli
