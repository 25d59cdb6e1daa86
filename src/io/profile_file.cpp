#include "io/profile_file.hpp"

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <map>
#include <sstream>

#include "core/errors.hpp"
#include "io/input_file.hpp"
#include "io/text_file.hpp"

namespace rollnoise::io {

using geometry::Profile;
using geometry::ProfileKind;
using geometry::to_string;

namespace {

std::string lower(std::string s) {
  std::transform(s.begin(), s.end(), s.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return s;
}

std::string extension(const std::string& path) {
  const auto slash = path.find_last_of('/');
  const auto dot = path.find_last_of('.');
  if (dot == std::string::npos || (slash != std::string::npos && dot < slash)) return "";
  return lower(path.substr(dot + 1));
}

[[noreturn]] void fail(const std::string& path, int line, const std::string& what) {
  throw InputError(path, path + ":" + std::to_string(line) + ": " + what);
}

std::vector<std::string> read_lines(const std::string& path) {
  std::istringstream in(read_input(path, path, "the profile file"));
  std::vector<std::string> lines;
  std::string l;
  while (std::getline(in, l)) lines.push_back(l);
  return lines;
}

// Parse a number (strtod: accepts "nan", "inf", which are then reported as not finite).
bool parse_number(const std::string& tok, double& v) {
  if (tok.empty()) return false;
  errno = 0;
  char* end = nullptr;
  v = std::strtod(tok.c_str(), &end);
  return end == tok.c_str() + tok.size();
}

// Split on ',', ';', tab and space; empty fields are dropped only for whitespace separators.
std::vector<std::string> split_fields(const std::string& line) {
  std::vector<std::string> out;
  std::string cur;
  bool has_delim = line.find_first_of(",;") != std::string::npos;
  for (char ch : line) {
    const bool sep = ch == ',' || ch == ';' || (!has_delim && (ch == ' ' || ch == '\t'));
    if (sep) {
      out.push_back(trim(cur));
      cur.clear();
    } else {
      cur += ch;
    }
  }
  out.push_back(trim(cur));
  if (!has_delim) {
    out.erase(std::remove(out.begin(), out.end(), std::string()), out.end());
  }
  return out;
}

// A point line: y and z, checked to be finite numbers. `line_no` is 1-based.
void parse_point(const std::string& path, int line_no, const std::vector<std::string>& f,
                 std::size_t min_fields, std::size_t max_fields, double& y, double& z) {
  if (f.size() < min_fields || f.size() > max_fields) {
    std::ostringstream m;
    m << "expected " << (min_fields == max_fields ? "" : "at least ") << min_fields
      << " numbers (y z in mm) but found " << f.size() << " field(s)";
    fail(path, line_no, m.str());
  }
  for (std::size_t k = 0; k < f.size(); ++k) {
    double v = 0.0;
    if (!parse_number(f[k], v)) fail(path, line_no, "'" + f[k] + "' is not a number");
    if (!std::isfinite(v)) fail(path, line_no, "'" + f[k] + "' is not a finite number");
    if (k == 0) y = v;
    if (k == 1) z = v;
  }
}

// Sorted y is required; a strictly decreasing file is accepted and reversed. Reports the first
// line that breaks the order.
void check_order(const std::string& path, const std::vector<double>& y,
                 const std::vector<int>& lines, const char* what) {
  if (y.size() < 2) return;
  const bool increasing = y[1] > y[0];
  for (std::size_t i = 1; i < y.size(); ++i) {
    const bool ok = increasing ? y[i] > y[i - 1] : y[i] < y[i - 1];
    if (!ok) {
      std::ostringstream m;
      m.precision(10);
      m << what << " y = " << y[i] << " after y = " << y[i - 1]
        << ": the lateral coordinate must be strictly monotone (sorted, no duplicates)";
      fail(path, lines[i], m.str());
    }
  }
}

void finish_points(const std::string& path, int last_line, std::vector<double>& y,
                   std::vector<double>& z, std::vector<int>& lines, const char* what) {
  if (static_cast<int>(y.size()) < Profile::min_points) {
    fail(path, last_line,
         "only " + std::to_string(y.size()) + " profile point(s), at least " +
             std::to_string(Profile::min_points) + " are needed");
  }
  check_order(path, y, lines, what);
  if (y[1] < y[0]) {
    std::reverse(y.begin(), y.end());
    std::reverse(z.begin(), z.end());
    std::reverse(lines.begin(), lines.end());
  }
}

std::optional<ProfileKind> kind_from_extension(const std::string& path) {
  const std::string e = extension(path);
  if (e == "prw") return ProfileKind::Wheel;
  if (e == "prr") return ProfileKind::Rail;
  return std::nullopt;
}

// A SIMPACK profile file as read: the key = value settings of the header and spline blocks (with
// the line each came from) and the points of the point block (with their lines).
struct SimpackFile {
  std::map<std::string, std::pair<std::string, int>> setting;
  std::vector<double> y, z;
  std::vector<int> where;
  int begin_line = 0;
  // the setting `key` as a number, `fallback` without it
  double number(const std::string& path, const std::string& key, double fallback) const {
    const auto it = setting.find(key);
    if (it == setting.end()) return fallback;
    double v = 0.0;
    if (!parse_number(it->second.first, v) || !std::isfinite(v))
      fail(path, it->second.second, "'" + key + "' = '" + it->second.first + "' is not a number");
    return v;
  }
  int line_of(const std::string& key) const {
    const auto it = setting.find(key);
    return it == setting.end() ? 0 : it->second.second;
  }
};

SimpackFile parse_simpack_blocks(const std::string& path, const std::vector<std::string>& lines) {
  SimpackFile f;
  bool in_points = false, seen_begin = false, seen_end = false;
  std::string block;  // header / spline
  for (std::size_t i = 0; i < lines.size(); ++i) {
    const int ln = static_cast<int>(i) + 1;
    std::string raw = lines[i];
    // The comment field of the spline block is quoted and may hold '!': read it first.
    std::string t = trim(raw);
    const auto bang = t.find('!');
    const auto quote = t.find('\'');
    if (bang != std::string::npos && (quote == std::string::npos || bang < quote))
      t = t.substr(0, bang);
    t = trim(t);
    if (t.empty()) continue;
    const std::string tl = lower(t);
    if (in_points) {
      if (tl == "point.end") {
        in_points = false;
        seen_end = true;
        continue;
      }
      double yy = 0.0, zz = 0.0;
      parse_point(path, ln, split_fields(t), 2, 3, yy, zz);
      f.y.push_back(yy);
      f.z.push_back(zz);
      f.where.push_back(ln);
      continue;
    }
    if (tl == "point.begin") {
      if (seen_begin) fail(path, ln, "a second point.begin block");
      in_points = seen_begin = true;
      f.begin_line = ln;
      continue;
    }
    if (tl.size() > 6 && tl.compare(tl.size() - 6, 6, ".begin") == 0) {
      block = tl.substr(0, tl.size() - 6);
      continue;
    }
    if (tl.size() > 4 && tl.compare(tl.size() - 4, 4, ".end") == 0) {
      block.clear();
      continue;
    }
    const auto eq = t.find('=');
    if (eq != std::string::npos) {
      std::string key = lower(trim(t.substr(0, eq)));
      std::string value = trim(t.substr(eq + 1));
      if (!value.empty() && value.front() == '\'') {
        const auto close = value.find('\'', 1);
        value = value.substr(1, close == std::string::npos ? std::string::npos : close - 1);
      }
      f.setting[(block.empty() ? "" : block + ".") + key] = {value, ln};
    }
  }
  if (!seen_begin)
    fail(path, static_cast<int>(lines.size()),
         "no point block: the file has no 'point.begin' ... 'point.end' section");
  if (!seen_end)
    fail(path, static_cast<int>(lines.size()),
         "the point block opened at line " + std::to_string(f.begin_line) + " has no closing 'point.end'");
  return f;
}

// Kind: header.type (0 rail, 1 wheel), else the extension, else the caller's.
ProfileKind simpack_kind(const std::string& path, const SimpackFile& f, std::optional<ProfileKind> kind) {
  std::optional<ProfileKind> file_kind;
  if (f.setting.count("header.type")) {
    const double t = f.number(path, "header.type", -1.0);
    if (t == 0.0)
      file_kind = ProfileKind::Rail;
    else if (t == 1.0)
      file_kind = ProfileKind::Wheel;
    else
      fail(path, f.line_of("header.type"),
           "header type = " + f.setting.at("header.type").first + " (expected 0 rail or 1 wheel)");
  }
  if (!file_kind) file_kind = kind_from_extension(path);
  if (!file_kind) file_kind = kind;
  if (!file_kind)
    fail(path, 1, "cannot tell a wheel from a rail profile: no header type, extension or caller hint");
  if (kind && *kind != *file_kind)
    fail(path, f.setting.count("header.type") ? f.line_of("header.type") : 1,
         std::string("the file is a ") + to_string(*file_kind) + " profile, a " + to_string(*kind) +
             " profile was expected");
  return *file_kind;
}

// The points after SIMPACK's processing flags in their numbered order: 2 shift, 3 rotate, 4
// bounds, 5 mirror, 6 inversion (data order only: the points are sorted again by finish_points), 7
// units; in metres, with their lines.
void apply_processing_flags(const std::string& path, const SimpackFile& f, std::vector<double>& py,
                            std::vector<double>& pz, std::vector<int>& pl) {
  const double shift_y = f.number(path, "spline.shift.y", 0.0), shift_z = f.number(path, "spline.shift.z", 0.0);
  const double units = f.number(path, "spline.units.len.f", 1000.0);  // lengths unit per metre
  const double units_ang = f.number(path, "spline.units.ang.f", 1.0);
  const double rotate = f.number(path, "spline.rotate", 0.0) / units_ang;
  const double bymin = f.number(path, "spline.bound.y.min", 1.0), bymax = f.number(path, "spline.bound.y.max", 0.0);
  const double bzmin = f.number(path, "spline.bound.z.min", 1.0), bzmax = f.number(path, "spline.bound.z.max", 0.0);
  const bool mirror_y = f.number(path, "spline.mirror.y", 0.0) != 0.0;
  const bool mirror_z = f.number(path, "spline.mirror.z", 0.0) != 0.0;
  if (!(units > 0.0)) fail(path, f.line_of("spline.units.len.f"), "units.len.f must be positive");
  const double c = std::cos(rotate), s = std::sin(rotate);
  for (std::size_t i = 0; i < f.y.size(); ++i) {
    double yy = f.y[i] + shift_y, zz = f.z[i] + shift_z;
    const double yr = c * yy - s * zz, zr = s * yy + c * zz;
    yy = yr;
    zz = zr;
    if (bymin < bymax && (yy < bymin || yy > bymax)) continue;  // min > max: bound disabled
    if (bzmin < bzmax && (zz < bzmin || zz > bzmax)) continue;
    if (mirror_y) yy = -yy;
    if (mirror_z) zz = -zz;
    py.push_back(yy / units);
    pz.push_back(zz / units);
    pl.push_back(f.where[i]);
  }
}

}  // namespace

Profile read_simpack_profile(const std::string& path, std::optional<ProfileKind> kind) {
  const std::vector<std::string> lines = read_lines(path);
  bool any = false;
  for (const auto& l : lines) any = any || !trim(l).empty();
  if (!any) fail(path, 1, "the profile file is empty");
  SimpackFile f = parse_simpack_blocks(path, lines);
  const ProfileKind file_kind = simpack_kind(path, f, kind);
  finish_points(path, f.begin_line, f.y, f.z, f.where, "point");
  std::vector<double> py, pz;
  std::vector<int> pl;
  apply_processing_flags(path, f, py, pz, pl);
  finish_points(path, f.begin_line, py, pz, pl, "after the file's processing flags, point");

  const std::string comment = lower(f.setting.count("spline.comment") ? f.setting.at("spline.comment").first : "");
  const bool canted = comment.find("already canted") != std::string::npos ||
                      (comment.find("canted") != std::string::npos &&
                       comment.find("not canted") == std::string::npos &&
                       comment.find("uncanted") == std::string::npos);
  return Profile(std::move(py), std::move(pz), file_kind, path, canted);
}

Profile read_csv_profile(const std::string& path, ProfileKind kind) {
  const std::vector<std::string> lines = read_lines(path);
  std::vector<double> y, z;
  std::vector<int> where;
  bool header_allowed = true;
  int last = 1;
  for (std::size_t i = 0; i < lines.size(); ++i) {
    const int ln = static_cast<int>(i) + 1;
    std::string t = lines[i];
    const auto hash = t.find('#');
    if (hash != std::string::npos) t = t.substr(0, hash);
    t = trim(t);
    if (t.empty()) continue;
    last = ln;
    const auto f = split_fields(t);
    double v = 0.0;
    if (header_allowed && !f.empty() && !parse_number(f[0], v)) {  // a header line: y_mm, z_mm
      header_allowed = false;
      continue;
    }
    header_allowed = false;
    double yy = 0.0, zz = 0.0;
    parse_point(path, ln, f, 2, 2, yy, zz);
    y.push_back(yy * 1e-3);
    z.push_back(zz * 1e-3);
    where.push_back(ln);
  }
  bool any = false;
  for (const auto& l : lines) any = any || !trim(l).empty();
  if (!any) fail(path, 1, "the profile file is empty");
  finish_points(path, last, y, z, where, "point");
  return Profile(std::move(y), std::move(z), kind, path, false);
}

Profile read_profile(const std::string& path, std::optional<ProfileKind> kind) {
  const std::string e = extension(path);
  bool simpack = e == "prw" || e == "prr" || e == "prf";
  if (!simpack && e != "csv") {
    for (const auto& l : read_lines(path))
      if (lower(l).find("point.begin") != std::string::npos) simpack = true;
  }
  if (simpack) return read_simpack_profile(path, kind);
  if (!kind)
    throw InputError(path, path +
                               ":1: a CSV profile file does not say whether it is a wheel or a "
                               "rail profile: give the kind");
  return read_csv_profile(path, *kind);
}

}  // namespace rollnoise::io
