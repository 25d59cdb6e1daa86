// Every key an input error names exists: each string literal key of `InputError("...", ...)` and
// `fail("...", ...)` in src/ (read at test time from ROLLNOISE_SOURCE_DIR) is a declared case key
// (io::find_key, src/io/case_schema.cpp), an option of the rollnoise program (declared in
// src/cli/main.cpp), or one of the pseudo-keys below, each with the reason it names no case key.
// Keys built at run time (a file path, "path:line") are not literals and are not checked here.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <map>
#include <regex>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include "io/case_schema.hpp"

namespace fs = std::filesystem;

namespace {

// The allow-list: pseudo-keys and why they are not case keys.
const std::map<std::string, std::string> kPseudoKeys = {
    {"(file)", "the case file itself could not be opened"},
    {"(syntax)", "the case file is not valid TOML"},
    // the keys of a study file (io/study_file.hpp, docs/study.md), not of a case file
    {"base", "study file: the base case"},
    {"output", "study file: the output folder"},
    {"combine", "study file: product or zip"},
    {"axes", "study file: the [axes] table"},
    {"axes.", "study file: one axis, axes.KEY (KEY a case key)"},
    {"SLURM_ARRAY_TASK_ID", "environment of a Slurm job array: the shard of a study"},
    {"grid", "the potential contact area as a whole: grid.scale or the explicit extent grid.x_min..y_max, "
             "whichever the case uses, or the grid the profile geometry chose"},
    {"geometry", "the wheel and rail profiles with the lateral displacement (contact.* or wheelset.*, "
                 "depending on curve.creepage) do not overlap"},
    {"contact.curvature", "the curvatures A, B of a profile contact: derived from the profiles, no key"},
    {"mesh_size", "argument of fem::mesh_polygon: the element size of a cross-section mesh"},
    {"outline", "argument of fem::mesh_polygon: the cross-section outline (a section file's points)"},
    {"tread_position", "argument: the contact's lateral position s on the wheel's running surface"},
    {"frequency", "a frequency argument of a numerics function; the case's frequencies are checked "
                  "against frequency.* and excitation.* where they are read"},
    {"contacts", "library guard: the contact set of the loop with several contacts (noise/contact_set.hpp; no "
                 "case keys yet, contacts[i].side etc. name the entry)"},
    {"sources", "library guard: one roughness amplitude per contact and source (noise/contact_set_loop.hpp)"},
    {"rail_material", "library guard: the waveguide rail's steel (dynamics::RailMaterial; no case key "
                      "yet)"},
    {"rail_support", "library guard: the waveguide rail's support (dynamics::FootSupport)"},
    {"rail_section", "library guard: the waveguide rail's section mesh (a flat foot, a head, edges)"},
    {"rail_reduction", "library guard: the waveguide rail's Ritz basis (dynamics::RailReduction)"},
    {"rail_contact", "library guard: the waveguide rail's load patch misses the section outline"},
    {"a_over_b", "argument of Kalker's coefficients (contact.a / contact.b or the patch)"},
    {"curving.contact_half_distance", "field of noise::BogieCurvingInput that no case key sets"},
    {"curving.contact_angle", "field of noise::BogieCurvingInput that no case key sets"},
    {"curving.flange_angle", "field of noise::BogieCurvingInput (or from the profiles); no key"},
    {"curving.flange_friction", "field of noise::BogieCurvingInput that no case key sets"},
    // fields of the model files named by case keys (track.file, wheel.modes, wheel.wheelset)
    {"head_height", "field of the track model file (track.file)"},
    {"sleeper_spacing", "field of the track model file (track.file)"},
    {"supports_each_side", "field of the track model file (track.file)"},
    {"damping_ratio", "column of the wheel modes file (wheel.modes)"},
    {"frequency_Hz", "column of the wheel modes file (wheel.modes)"},
    {"modal_mass_kg", "column of the wheel modes file (wheel.modes)"},
    {"phi_z", "column of the wheel modes file (wheel.modes)"},
};

struct Use {
  std::string key, where;
};

// The text of a line before a // comment that is not inside a string literal.
std::string strip_comment(const std::string& line) {
  bool in_string = false;
  for (size_t i = 0; i + 1 < line.size(); ++i) {
    if (line[i] == '\\' && in_string) {
      ++i;
      continue;
    }
    if (line[i] == '"') in_string = !in_string;
    if (!in_string && line[i] == '/' && line[i + 1] == '/') return line.substr(0, i);
  }
  return line;
}

std::vector<Use> literal_keys() {
  const std::regex call(R"re(\b(InputError|fail)\(\s*"((?:[^"\\]|\\.)*)")re");
  std::vector<Use> uses;
  for (const auto& entry : fs::recursive_directory_iterator(fs::path(ROLLNOISE_SOURCE_DIR) / "src")) {
    const auto ext = entry.path().extension();
    if (!entry.is_regular_file() || (ext != ".cpp" && ext != ".hpp")) continue;
    std::ifstream in(entry.path());
    std::string text, line;
    std::vector<size_t> line_start;  // offset of each line in `text`
    while (std::getline(in, line)) line_start.push_back(text.size()), text += strip_comment(line) + "\n";
    for (std::sregex_iterator m(text.begin(), text.end(), call), end; m != end; ++m) {
      const size_t at = static_cast<size_t>(m->position(0));
      const size_t n = std::upper_bound(line_start.begin(), line_start.end(), at) - line_start.begin();
      uses.push_back({(*m)[2].str(), fs::relative(entry.path(), ROLLNOISE_SOURCE_DIR).string() + ":" +
                                         std::to_string(n)});
    }
  }
  return uses;
}

std::set<std::string> cli_options() {
  // the names in add_option/add_flag("-o,--output", ...) of src/cli/main.cpp
  std::ifstream in(fs::path(ROLLNOISE_SOURCE_DIR) / "src/cli/main.cpp");
  std::stringstream ss;
  ss << in.rdbuf();
  const std::string text = ss.str();
  const std::regex decl(R"re(add_(?:option|flag)\(\s*"([^"]*)")re");
  std::set<std::string> names;
  for (std::sregex_iterator m(text.begin(), text.end(), decl), end; m != end; ++m) {
    std::stringstream list((*m)[1].str());
    for (std::string name; std::getline(list, name, ',');) names.insert(name);
  }
  return names;
}

}  // namespace

TEST(ErrorKeys, EveryLiteralKeyIsACaseKeyAnOptionOrAListedPseudoKey) {
  const auto uses = literal_keys();
  ASSERT_GT(uses.size(), 50u);  // the scan found the sources
  const auto options = cli_options();
  ASSERT_TRUE(options.count("--csv") && options.count("--set")) << "main.cpp's options not found";
  for (const Use& u : uses) {
    const bool declared = rollnoise::io::find_key(u.key) != nullptr;
    const bool option = u.key.rfind('-', 0) == 0 && options.count(u.key) > 0;
    EXPECT_TRUE(declared || option || kPseudoKeys.count(u.key))
        << u.where << ": InputError key \"" << u.key
        << "\" is no case key (rollnoise keys), no option of rollnoise and not in the pseudo-key list";
  }
}

TEST(ErrorKeys, EveryListedPseudoKeyIsStillUsed) {
  // the allow-list holds no stale entries (and no real case key)
  std::set<std::string> used;
  for (const Use& u : literal_keys()) used.insert(u.key);
  for (const auto& [key, reason] : kPseudoKeys) {
    EXPECT_TRUE(used.count(key)) << "pseudo-key \"" << key << "\" is no longer used: remove it";
    EXPECT_EQ(rollnoise::io::find_key(key), nullptr) << key << " is a case key: remove it from the list";
  }
}

// Keys in messages built at run time. Each invocation fails with exit 2 and the
// message "rollnoise: error: CASE: KEY: ..." names a declared case key (or an option), never a
// field of the numerics (curving.flange_angle) nor a bare "filesystem error"; --case names the
// option without printing the largest double as its range.
#include "../cli/cli_support.hpp"

namespace {

// The key in "rollnoise: error: CASE: KEY: ..." or, for a value a --set gave, "--set KEY: ..." (or,
// for several problems, in the first such line after "rollnoise: error: N problems in the case:"),
// or "".
std::string key_after(const std::string& output, const std::string& case_file) {
  const auto error = output.find("rollnoise: error: ");
  if (error == std::string::npos) return "";
  for (const std::string& before : {case_file + ": ", std::string("--set ")}) {
    const auto at = output.find(before, error);
    if (at == std::string::npos) continue;
    const auto from = at + before.size();
    return output.substr(from, output.find(':', from) - from);
  }
  return "";
}

}  // namespace

TEST(ErrorKeys, KeysNamedInMessagesBuiltAtRunTimeAreCaseKeys) {
  using rollnoise::cli_test::run;
  const fs::path d = rollnoise::cli_test::temp_dir() / "runtime_keys";
  fs::remove_all(d);
  fs::create_directories(d / "profile_folder");
  fs::create_symlink(d / "loop_a", d / "loop_b");
  fs::create_symlink(d / "loop_b", d / "loop_a");
  const std::string hertz = rollnoise::cli_test::paper_case();
  const std::string curve = rollnoise::cli_test::source_file("cases/curve_300m.toml");
  const std::string out = " -q -o " + (d / "x.h5").string();
  const std::string profiles = " --set contact.geometry=profiles";
  struct Failure {
    std::string args, case_file, key;
  };
  const std::vector<Failure> failures = {
      {"noise " + curve + out + " --set friction.mu=10", curve, "friction.mu"},
      {"receptance " + curve + out + " --set track.rail_section=models/rail/uic60_outline.csv", curve,
       "track.rail_section"},
      {"steady " + hertz + out + profiles + " --set contact.wheel_profile=" + (d / "loop_a").string(), hertz,
       "contact.wheel_profile"},
      {"steady " + hertz + out + profiles + " --set contact.rail_profile=" + (d / "profile_folder").string(), hertz,
       "contact.rail_profile"},
      {"steady " + hertz + out + profiles + " --set grid.x_min=-0.02 --set grid.x_max=0.02 --set grid.y_min=-0.02 "
       "--set grid.y_max=0.02",
       hertz, "grid.x_min"},
  };
  for (const Failure& f : failures) {
    const auto r = run(f.args);
    EXPECT_EQ(r.status, 2) << f.args << "\n" << r.output;
    const std::string key = key_after(r.output, f.case_file);
    EXPECT_EQ(key, f.key) << f.args << "\n" << r.output;
    EXPECT_NE(rollnoise::io::find_key(key), nullptr) << key << " is no case key:\n" << r.output;
    EXPECT_EQ(r.output.find("filesystem error"), std::string::npos) << r.output;
  }
  const auto r = run("study " + rollnoise::cli_test::source_file("cases/study_300m_radius_speed.toml") + " --case -1");
  EXPECT_EQ(r.status, 2) << r.output;
  EXPECT_NE(r.output.find("--case"), std::string::npos) << r.output;
  EXPECT_EQ(r.output.find("1.79769e+308"), std::string::npos) << r.output;
  fs::remove_all(d);
}
