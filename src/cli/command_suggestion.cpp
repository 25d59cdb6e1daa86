#include "cli/command_suggestion.hpp"

#include <CLI/CLI.hpp>
#include <algorithm>
#include <numeric>

namespace rollnoise::cli {

std::size_t edit_distance(const std::string& a, const std::string& b) {
  std::vector<std::size_t> row(b.size() + 1);
  std::iota(row.begin(), row.end(), 0);
  for (std::size_t i = 1; i <= a.size(); ++i) {
    std::size_t diagonal = row[0];
    row[0] = i;
    for (std::size_t j = 1; j <= b.size(); ++j) {
      const std::size_t up = row[j];
      row[j] = std::min({row[j] + 1, row[j - 1] + 1, diagonal + (a[i - 1] == b[j - 1] ? 0 : 1)});
      diagonal = up;
    }
  }
  return row[b.size()];
}

std::string unknown_command_message(const std::string& given,
                                    const std::vector<std::string>& commands) {
  std::string msg = "unknown command '" + given + "'";
  const std::string* best = nullptr;
  std::size_t best_distance = 0;
  for (const auto& c : commands) {
    const std::size_t d = edit_distance(given, c);
    if (!best || d < best_distance) best = &c, best_distance = d;
  }
  if (best && best_distance <= std::max<std::size_t>(2, best->size() / 3))
    msg += "; did you mean '" + *best + "'?";
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
