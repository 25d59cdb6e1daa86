// Readers of CONTACT's .out, .mat and .inp files (contact_results.hpp; the formats are described
// in docs/contact_interop.md Sec. 4).
#include "io/contact_results.hpp"

#include <cmath>
#include <cstdlib>
#include <set>
#include <sstream>

#include "core/errors.hpp"
#include "io/input_file.hpp"
#include "io/text_file.hpp"

namespace rollnoise::io {
namespace {

std::vector<std::string> words(const std::string& line) {
  std::istringstream in(line);
  std::vector<std::string> w;
  for (std::string s; in >> s;) w.push_back(s);
  return w;
}

std::vector<std::string> read_lines(const std::string& path, const std::string& what) {
  std::istringstream in(read_input(path, path, "the CONTACT " + what));
  std::vector<std::string> lines;
  for (std::string l; std::getline(in, l);) {
    if (!l.empty() && l.back() == '\r') l.pop_back();
    lines.push_back(l);
  }
  return lines;
}

[[noreturn]] void fail(const std::string& path, std::size_t line_index, const std::string& msg) {
  throw InputError(path, path + ":" + std::to_string(line_index + 1) + ": " + msg);
}

/// All words of `w` numbers: their values; else empty (and false).
bool all_numbers(const std::vector<std::string>& w, std::vector<double>& v) {
  v.clear();
  for (const auto& s : w) {
    double x;
    if (!parse_fortran_number(s, x)) return false;
    v.push_back(x);
  }
  return !w.empty();
}

bool no_numbers(const std::vector<std::string>& w) {
  for (const auto& s : w) {
    double x;
    if (parse_fortran_number(s, x)) return false;
  }
  return true;
}

// The header lines of .out whose line of numbers a reader relies on (first word).
const std::set<std::string> kRequiredHeaders = {"FN",   "FN/G",  "NPOT",    "CHI",   "FX(TR)",
                                                "S_WS", "VX_WS", "XCP(TR)", "XCP(W)"};

const char* kEndLine = "The CONTACT program ended succesfully.";  // CONTACT's spelling

}  // namespace

bool parse_fortran_number(const std::string& text, double& value) {
  std::string s = trim(text);
  if (s.empty()) return false;
  for (auto& c : s)
    if (c == 'D' || c == 'd') c = 'E';  // Fortran double-precision exponent
  // g14.6 writes a 3-digit exponent without its letter: 0.228751-310 = 0.228751E-310
  for (std::size_t p = 1; p < s.size(); ++p)
    if ((s[p] == '-' || s[p] == '+') &&
        (std::isdigit(static_cast<unsigned char>(s[p - 1])) || s[p - 1] == '.')) {
      s.insert(p, "E");
      break;
    }
  const char c0 = s[0];
  if (!(std::isdigit(static_cast<unsigned char>(c0)) || c0 == '-' || c0 == '+' || c0 == '.'))
    return false;
  const bool ok = parse_finite(s, value);
  if (!ok && s.find('E') != std::string::npos) {  // a subnormal such as 0.228751E-310
    char* end = nullptr;
    const double v = std::strtod(s.c_str(), &end);
    if (end == s.c_str() + s.size() && std::isfinite(v)) {
      value = v;
      return true;
    }
  }
  return ok;
}

double ContactOutPatch::at(const std::string& name, const std::string& where) const {
  const auto it = values.find(name);
  if (it == values.end())
    throw InputError(where,
                     where + ": no value " + name + " in contact patch " + std::to_string(number));
  return it->second;
}

ContactOut read_contact_out(const std::string& path) {
  const std::vector<std::string> lines = read_lines(path, "output");
  ContactOut out;
  out.path = path;
  bool ended = false;
  ContactOutCase* c = nullptr;
  for (std::size_t i = 0; i < lines.size(); ++i) {
    const std::vector<std::string> w = words(lines[i]);
    if (w.empty()) continue;
    if (lines[i].find("$Revision:") != std::string::npos) {
      const auto r = words(lines[i].substr(lines[i].find("$Revision:") + 10));
      if (!r.empty()) out.revision = r[0];
    }
    if (trim(lines[i]) == kEndLine) {
      ended = true;
      break;
    }
    if (w.size() == 2 && w[0] == "Case") {
      out.cases.push_back({});
      c = &out.cases.back();
      c->number = std::atoi(w[1].c_str());
      c->line = static_cast<int>(i + 1);
      continue;
    }
    if (!c) continue;
    if (lines[i].find("WHEEL-RAIL CONTACT") != std::string::npos) c->module = 1;
    if (w.size() >= 5 && w[0] == "-----" && w[1] == "DATA" && w[4] == "PATCH") {
      c->patches.push_back({});
      c->patches.back().number = std::atoi(w[5].c_str());
      continue;
    }
    if (w.size() < 2 || !no_numbers(w)) continue;
    // a header of names: its values on the next line, one number per name
    std::vector<double> v;
    const bool required = kRequiredHeaders.count(w[0]) > 0;
    const bool pair =
        i + 1 < lines.size() && all_numbers(words(lines[i + 1]), v) && v.size() == w.size();
    if (!pair) {
      if (required)
        fail(path, i + 1,
             "expected the " + std::to_string(w.size()) + " numbers of '" + trim(lines[i]) +
                 "' (truncated or not a CONTACT .out file?)");
      continue;
    }
    const bool per_patch = c->module == 3 || !c->patches.empty();
    if (per_patch && c->patches.empty()) c->patches.push_back({});
    NamedValues& target = per_patch ? c->patches.back().values : c->values;
    for (std::size_t k = 0; k < w.size(); ++k) target[w[k]] = v[k];
    ++i;
  }
  if (out.cases.empty())
    fail(path, lines.size() ? lines.size() - 1 : 0, "no ' Case n' block: not a CONTACT .out file");
  if (!ended)
    fail(path, lines.size() ? lines.size() - 1 : 0,
         "the file ends without CONTACT's last line '" + std::string(kEndLine) + "' (truncated?)");
  for (const auto& cs : out.cases)
    if (cs.patches.empty() || !cs.patches.front().values.count("FN"))
      fail(path, std::size_t(cs.line - 1),
           "case " + std::to_string(cs.number) + " prints no total forces (FN FX ...)");
  return out;
}

double ContactMat::header_value(const std::string& name) const {
  const auto it = header.find(name);
  if (it == header.end()) throw InputError(path, path + ": the header holds no " + name);
  return it->second;
}

const std::vector<double>& ContactMat::column(const std::string& name) const {
  const auto it = columns.find(name);
  if (it == columns.end()) throw InputError(path, path + ": no column " + name);
  return it->second;
}

double ContactMat::x(std::size_t r) const {
  const long I = std::lround(columns.at("I")[r]);
  return header.at("XL") + (double((I - 1) % mx()) + 0.5) * header.at("DX");
}

double ContactMat::y(std::size_t r) const {
  const long I = std::lround(columns.at("I")[r]);
  return header.at("YL") + (double((I - 1) / mx()) + 0.5) * header.at("DY");
}

ContactMat read_contact_mat(const std::string& path) {
  const std::vector<std::string> lines = read_lines(path, "traction file");
  ContactMat m;
  m.path = path;
  std::size_t i = 0;
  // header pairs: "% NAMES" then a line of values; the pair whose names start "I IGS" opens the
  // table
  for (; i < lines.size(); ++i) {
    const std::string t = trim(lines[i]);
    if (t.empty()) continue;
    if (t[0] != '%') fail(path, i, "expected a '%' header line of names");
    std::vector<std::string> names = words(t.substr(1));
    if (names.size() >= 2 && names[0] == "I" && names[1] == "IGS") {
      m.column_names = names;
      ++i;
      break;
    }
    std::vector<double> v;
    if (i + 1 >= lines.size() || !all_numbers(words(lines[i + 1]), v))
      fail(path, i + 1, "expected the numbers of header '" + t + "'");
    for (std::size_t k = 0; k < names.size() && k < v.size(); ++k)
      if (names[k] != "-") m.header[names[k]] = v[k];
    ++i;
  }
  if (m.column_names.empty())
    fail(path, lines.size() ? lines.size() - 1 : 0, "no column line '% I IGS ...'");
  const auto fmt = m.header.find("FMT");
  if (fmt == m.header.end() || fmt->second != 2410)
    fail(path, 1,
         "format FMT = " +
             (fmt == m.header.end() ? std::string("(none)") : std::to_string(long(fmt->second))) +
             "; this reader knows 2410");
  for (const char* k : {"MX", "MY", "XL", "YL", "DX", "DY"})
    if (!m.header.count(k)) fail(path, 0, std::string("the header holds no ") + k);
  for (const auto& n : m.column_names) m.columns[n];
  const long n_elements = long(m.mx()) * m.my();
  std::vector<double> v;
  for (; i < lines.size(); ++i) {
    const std::vector<std::string> w = words(lines[i]);
    if (w.empty()) continue;
    if (w.size() != m.column_names.size() || !all_numbers(w, v))
      fail(path, i,
           "an element row needs " + std::to_string(m.column_names.size()) + " numbers (" +
               std::to_string(w.size()) + " words; truncated?)");
    if (v[0] < 1 || v[0] > double(n_elements) || v[0] != std::floor(v[0]))
      fail(path, i, "element number I = " + w[0] + " outside 1.." + std::to_string(n_elements));
    for (std::size_t k = 0; k < v.size(); ++k) m.columns[m.column_names[k]].push_back(v[k]);
  }
  if (m.rows() == 0) fail(path, lines.size() ? lines.size() - 1 : 0, "no element rows");
  return m;
}

ContactMatTotals integrate(const ContactMat& m) {
  ContactMatTotals t;
  const double area = m.header_value("DX") * m.header_value("DY");
  const auto& pn = m.column("PN");
  const auto& px = m.column("PX");
  const auto& py = m.column("PY");
  const auto& igs = m.column("IGS");
  for (std::size_t r = 0; r < m.rows(); ++r) {
    t.Fn += area * pn[r];
    t.Fx += area * px[r];
    t.Fy += area * py[r];
    t.Mz += area * (py[r] * m.x(r) - px[r] * m.y(r));
    t.max_pn = std::max(t.max_pn, pn[r]);
    const int s = int(igs[r]);
    (s == 1 ? t.n_adhesion : s == 2 ? t.n_slip : t.n_exterior)++;
  }
  return t;
}

const ContactInpLine* ContactInpCase::find(const std::string& label_start) const {
  for (const auto& l : lines)
    if (l.label.compare(0, label_start.size(), label_start) == 0) return &l;
  return nullptr;
}

std::vector<ContactInpCase> parse_contact_inp(const std::string& text, const std::string& name) {
  std::vector<ContactInpCase> cases;
  std::istringstream in(text);
  std::string raw;
  int line_no = 0;
  bool ended = false;
  while (std::getline(in, raw)) {
    ++line_no;
    const std::string t = trim(raw);
    if (t.empty() || t[0] == '%') continue;
    ContactInpLine l;
    l.line = line_no;
    std::size_t p = 0;
    // values first: numbers and 'quoted strings'; the rest of the line is the label
    while (p < t.size()) {
      while (p < t.size() && std::isspace(static_cast<unsigned char>(t[p]))) ++p;
      if (p < t.size() && t[p] == '\'') {
        const std::size_t q = t.find('\'', p + 1);
        if (q == std::string::npos)
          throw InputError(name, name + ":" + std::to_string(line_no) + ": unclosed quote");
        l.strings.push_back(t.substr(p + 1, q - p - 1));
        p = q + 1;
        continue;
      }
      std::size_t e = p;
      while (e < t.size() && !std::isspace(static_cast<unsigned char>(t[e]))) ++e;
      double v;
      if (!parse_fortran_number(t.substr(p, e - p), v)) break;
      l.numbers.push_back(v);
      p = e;
    }
    l.label = trim(t.substr(std::min(p, t.size())));
    if (l.label.rfind("MODULE", 0) == 0 && l.numbers.size() == 1) {
      if (l.numbers[0] == 0) {
        ended = true;
        break;
      }
      cases.push_back({});
      cases.back().module = int(l.numbers[0]);
      continue;
    }
    if (cases.empty())
      throw InputError(
          name, name + ":" + std::to_string(line_no) + ": data before the first 'n MODULE' line");
    cases.back().lines.push_back(l);
  }
  if (!ended)
    throw InputError(name, name + ":" + std::to_string(line_no) +
                               ": no ' 0 MODULE' line ends the input (truncated?)");
  return cases;
}

std::vector<ContactInpCase> read_contact_inp(const std::string& path) {
  return parse_contact_inp(read_input(path, path, "the CONTACT input"), path);
}

}  // namespace rollnoise::io
