#include "io/cnossos_output.hpp"

#include <cstdio>
#include <sstream>

#include "io/output_files.hpp"

namespace rollnoise::io {

namespace {

// A JSON array of numbers (%.17g: read back exactly) or of booleans.
template <class T>
std::string array(const T& values) {
  std::ostringstream os;
  os << "[";
  for (std::size_t i = 0; i < values.size(); ++i) {
    char text[32];
    if constexpr (std::is_same_v<typename T::value_type, bool>)
      std::snprintf(text, sizeof text, "%s", values[i] ? "true" : "false");
    else
      std::snprintf(text, sizeof text, "%.17g", values[i]);
    os << (i ? ", " : "") << text;
  }
  return os.str() + "]";
}

std::string filled_note(const pipeline::CnossosTransfer& t) {
  std::string bands;
  for (std::size_t i = 0; i < pipeline::kCnossosBands; ++i)
    if (!t.computed[i]) {
      char text[16];
      std::snprintf(text, sizeof text, "%s%g", bands.empty() ? "" : ", ",
                    pipeline::cnossos_centres()[i]);
      bands += text;
    }
  return bands.empty() ? "none: every band computed"
                       : bands +
                             " Hz: outside the case's bands (noise.band_min .. noise.band_max), "
                             "not computed; "
                             "each holds the value of the nearest computed band";
}

}  // namespace

std::string cnossos_json(const pipeline::CnossosTransfer& t, const CnossosOrigin& o) {
  char speed[64];
  std::snprintf(speed, sizeof speed, "%.1f km/h", o.speed);
  const std::string ref = "rollnoise, case " + o.case_name + " at " + speed;
  const std::string filled = filled_note(t);
  std::ostringstream os;
  os << "{\n  \"Vehicle\": {\n    \"Transfer\": {\n      \"1000\": {\n        \"Default\": "
        "\"false\",\n"
     << "        \"Reference\": \"" << ref << "\",\n"
     << "        \"Description\": \"L_H,VEH: wheel sound power per axle minus L_R,TOT (dB); filled "
        "bands: "
     << filled << "\",\n        \"WheelDiameter\": " << o.wheel_diameter
     << ",\n        \"WheelDiameterCode\": null,\n"
     << "        \"Spectre\": " << array(t.vehicle) << "\n      }\n    }\n  },\n"
     << "  \"Track\": {\n    \"TrackTransfer\": {\n      \"1000\": {\n        \"Default\": "
        "\"false\",\n"
     << "        \"Reference\": \"" << ref << "\",\n"
     << "        \"Description\": \"L_H,TR: rail and sleeper sound power per axle minus L_R,TOT "
        "(dB); filled bands: "
     << filled << "\",\n        \"Spectre\": " << array(t.track) << "\n      }\n    }\n  },\n"
     << "  \"rollnoise\": {\n    \"band_centre\": " << array(pipeline::cnossos_centres()) << ",\n"
     << "    \"computed\": " << array(t.computed) << ",\n    \"filled\": \"" << filled << "\",\n"
     << "    \"roughness_total\": " << array(t.roughness) << ",\n"
     << "    \"units\": \"Spectre: dB (sound power per axle in dB re 1 pW minus L_R,TOT in dB re 1 "
        "um); "
        "roughness_total: dB re 1 um; band_centre: Hz\"\n  }\n}\n";
  return os.str();
}

void write_cnossos(const std::string& path, const std::string& option,
                   const pipeline::CnossosTransfer& t, const CnossosOrigin& origin) {
  TemporaryFile f =
      write_text_file(path, option, [&](std::ostream& out) { out << cnossos_json(t, origin); });
  f.commit();
}

}  // namespace rollnoise::io
