// Reading the results of CONTACT (Vollebregt & Kalker, the open-source stand-alone program;
// docs/contact_interop.md): its text output `.out` (the totals per case and per contact patch,
// module 3 and module 1), its traction files `.mat` (format 2410, header values by name, one row
// per element) and the numbers of its input `.inp` (per case, each data line's values and label).
//
// CONTACT's own units are kept here (mm, N, N/mm^2, N mm, rad/mm); conversion to rollnoise's SI
// and its sign conventions is io/contact_reference.hpp's job. Numbers are Fortran-formatted
// (F, E and g14.6 output, including a 3-digit exponent written without `E`: 0.228751-310).
// A file that is not what its reader expects (no end line, a value line cut short, a number
// that is not one) throws InputError whose message names the file and line (exit status 2).
#pragma once

#include <map>
#include <string>
#include <vector>

namespace rollnoise::io {

/// A number in Fortran output: "1.5", "-8965.", "9.810E+04", "0.228751-310" (g14.6 with a
/// 3-digit exponent, no E). False if `s` is not one.
bool parse_fortran_number(const std::string& s, double& value);

/// The values printed under a header line of names (`FN FX FY MZ ELAST.EN. FRIC.POWER`),
/// by name; a name seen twice keeps its last value.
using NamedValues = std::map<std::string, double>;

/// One contact patch of a case in `.out`: KINEMATIC CONSTANTS, the forces (module 3: FN FX FY MZ;
/// module 1: FN FX FS MN), FN/G ... APPROACH PMAX, CONTACT STATISTICS (NPOT NCON NADH NSLIP),
/// module 1 also the CONTACT REFERENCE LOCATION (XCP(TR) ...).
struct ContactOutPatch {
  int number = 1;
  NamedValues values;
  double at(const std::string& name, const std::string& where) const;
};

/// One case (` Case n`) of `.out`.
struct ContactOutCase {
  int number = 0;
  int module = 3;      ///< 3 (basic contact problems) or 1 (wheel-rail contact)
  int line = 0;        ///< line of ` Case n` (for messages)
  NamedValues values;  ///< case-wide values: module 1 FX(TR) ... FZ(WS), S_WS ..., VX_WS ...
  std::vector<ContactOutPatch> patches;  ///< module 3: one
};

struct ContactOut {
  std::string path;
  std::string revision;  ///< the banner's "$Revision: 2707 $" number, or empty
  std::vector<ContactOutCase> cases;
};

/// Reads CONTACT's `.out`. InputError "PATH:LINE: ..." (key PATH) when it cannot be opened, holds
/// no case, a known header (FN FX ..., FN/G ..., NPOT ..., CHI DQ ..., FX(TR) ...) is not followed
/// by its line of numbers, or the end line (" The CONTACT program ended succesfully.") is missing.
ContactOut read_contact_out(const std::string& path);

/// A `.mat` traction file: the header values by their names (MX, MY, XL, YL, DX, DY, T, VELOC,
/// FMT, ...; unused columns "-" dropped) and the element table, one column per name (I, IGS, H,
/// MU, PN, PX, PY, UN, UX, UY, SREL, ...).
struct ContactMat {
  std::string path;
  NamedValues header;
  std::vector<std::string> column_names;
  std::map<std::string, std::vector<double>> columns;

  std::size_t rows() const { return columns.empty() ? 0 : columns.begin()->second.size(); }
  double header_value(const std::string& name) const;
  const std::vector<double>& column(const std::string& name) const;
  int mx() const { return static_cast<int>(header_value("MX")); }
  int my() const { return static_cast<int>(header_value("MY")); }
  /// Centre (mm) of the element in row r: x = XL + (ix - 1/2) DX, y = YL + (iy - 1/2) DY with
  /// ix = (I - 1) mod MX + 1, iy = (I - 1) div MX + 1.
  double x(std::size_t r) const;
  double y(std::size_t r) const;
};

/// Reads a `.mat` of format FMT = 2410. InputError naming the file and line for another format, a
/// missing MX MY XL YL DX DY, a row with too few or bad numbers, or an element number I outside
/// 1..MX*MY.
ContactMat read_contact_mat(const std::string& path);

/// The totals of a traction file, integrated over its rows (CONTACT's units and signs: tractions
/// on body 1): Fn = DX DY sum PN, Fx = DX DY sum PX, Fy = DX DY sum PY (N),
/// Mz = DX DY sum (PY x - PX y) (N mm, about the grid's origin), and the element counts by IGS.
struct ContactMatTotals {
  double Fn = 0, Fx = 0, Fy = 0, Mz = 0;
  double max_pn = 0;  ///< N/mm^2
  int n_adhesion = 0, n_slip = 0, n_exterior = 0;
};
ContactMatTotals integrate(const ContactMat& m);

/// One data line of a `.inp`: its numbers (digit words as numbers too), quoted strings, and the
/// label text after them (e.g. "FN, CKSI, CETA, CPHI").
struct ContactInpLine {
  int line = 0;
  std::vector<double> numbers;
  std::vector<std::string> strings;
  std::string label;
};

/// One case of a `.inp` (from "n MODULE" to the next): its module number and data lines.
struct ContactInpCase {
  int module = 3;
  std::vector<ContactInpLine> lines;
  /// The line whose label starts with `label_start` (e.g. "FN, CKSI"), or nullptr.
  const ContactInpLine* find(const std::string& label_start) const;
};

/// Reads the numbers of a `.inp` case by case (comment lines "%" and blank lines skipped; the
/// file ends at " 0 MODULE"). InputError naming the file and line when no "0 MODULE" ends it.
std::vector<ContactInpCase> read_contact_inp(const std::string& path);

/// The same from text (`name` for the messages).
std::vector<ContactInpCase> parse_contact_inp(const std::string& text, const std::string& name);

}  // namespace rollnoise::io
