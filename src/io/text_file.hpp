// Small text helpers shared by the model-file readers of io (profile_file, wheel_file,
// roughness_file): trimming, CSV cells, numbers, and the loop over the data lines of a file (blank
// lines and '#' comments skipped, "path:line" kept for error messages).
#pragma once

#include <cctype>
#include <cmath>
#include <exception>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "core/errors.hpp"
#include "io/input_file.hpp"

namespace rollnoise::io {

/// `s` without leading and trailing white space.
inline std::string trim(const std::string& s) {
  std::size_t b = 0, e = s.size();
  while (b < e && std::isspace(static_cast<unsigned char>(s[b]))) ++b;
  while (e > b && std::isspace(static_cast<unsigned char>(s[e - 1]))) --e;
  return s.substr(b, e - b);
}

/// The comma-separated cells of `line`, trimmed; a trailing comma gives a last empty cell.
inline std::vector<std::string> split_csv(const std::string& line) {
  std::vector<std::string> out;
  std::stringstream ss(line);
  std::string cell;
  while (std::getline(ss, cell, ',')) out.push_back(trim(cell));
  if (!line.empty() && line.back() == ',') out.push_back("");
  return out;
}

/// True if the whole of `cell` is a finite number (then stored in `value`).
inline bool parse_finite(const std::string& cell, double& value) {
  std::size_t used = 0;
  try {
    value = std::stod(cell, &used);
  } catch (const std::exception&) {
    return false;
  }
  return used > 0 && used == cell.size() && std::isfinite(value);
}

/// Calls row(where, line) for every line of the text file `path` that is neither blank nor a '#'
/// comment, with the trimmed line and where = "path:line number". The file is read once
/// (read_input); InputError (key `path`) if it cannot be read; `what` names its kind in the message.
template <class Row>
void for_each_data_line(const std::string& path, const std::string& what, Row&& row) {
  std::istringstream in(read_input(path, path, what));
  std::string line;
  for (int line_no = 1; std::getline(in, line); ++line_no) {
    const std::string t = trim(line);
    if (t.empty() || t[0] == '#') continue;
    row(path + ":" + std::to_string(line_no), t);
  }
}

}  // namespace rollnoise::io
