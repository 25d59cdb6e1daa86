#include "cli/run_files.hpp"

#include <cstdio>

#include "io/case_reader.hpp"
#include "io/output_files.hpp"

namespace rollnoise::cli {

void start_process(int argc, char** argv) {
  std::setvbuf(stdout, nullptr, _IOLBF, 0);
  io::record_invocation(argc, argv);
}

void check_run_files(const CommonOptions& o, const std::string& csv) {
  const io::CaseReader reader = io::CaseReader::from_file(o.case_file, o.overrides);
  std::vector<io::OutputFile> outputs;
  outputs.push_back({"-o", output_path(o, reader.name())});
  if (!csv.empty()) outputs.push_back({"--csv", csv});
  io::check_outputs(outputs, io::case_input_files(reader));
}

}  // namespace rollnoise::cli
