// A mistyped command (`rollnoise stedy CASE`): name it, list the valid commands and suggest the
// nearest by edit distance, instead of CLI11's "A subcommand is required".
#pragma once

#include <string>
#include <vector>

namespace CLI {
class App;
}

namespace rollnoise::cli {

/// The message for `given`, not one of `commands`: the valid ones and, when one is within an
/// edit distance of max(2, a third of its length), "did you mean 'X'?".
std::string unknown_command_message(const std::string& given,
                                    const std::vector<std::string>& commands);

/// The message when argv[1] is neither an option nor a subcommand of `app`; empty otherwise.
std::string check_command(const CLI::App& app, int argc, char** argv);

}  // namespace rollnoise::cli
