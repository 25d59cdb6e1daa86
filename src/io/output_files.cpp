#include "io/output_files.hpp"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <climits>
#include <csignal>
#include <cstring>
#include <ctime>
#include <filesystem>
#include <stdexcept>

#include "core/errors.hpp"
#include "io/excitation.hpp"
#include "io/hdf5_reader.hpp"
#include "rollnoise_version.h"  // generated at build time by cmake/version.cmake

namespace rollnoise::io {
namespace fs = std::filesystem;

namespace {

// ---- the temporaries the signal handler removes ----
// A fixed table (no allocation, no locks in the handler): a slot is filled, then marked used; the
// handler unlinks the paths of the used slots. Changes happen with the handled signals blocked, so
// the handler never sees a half-written slot.
constexpr int kSlots = 16;
constexpr std::size_t kPathMax = 4096;
char g_paths[kSlots][kPathMax];
volatile std::sig_atomic_t g_used[kSlots];
constexpr int kSignals[] = {SIGINT, SIGTERM, SIGHUP};
bool g_handlers_installed = false;

extern "C" void remove_temporaries_and_reraise(int sig) {
  for (int i = 0; i < kSlots; ++i)
    if (g_used[i]) ::unlink(g_paths[i]);
  // SA_RESETHAND restored the default action; the signal is blocked while we run and is delivered
  // again on return, so the process ends as killed by it (the exit status shows the signal).
  ::raise(sig);
}

void install_handlers() {
  if (g_handlers_installed) return;
  g_handlers_installed = true;
  for (int sig : kSignals) {
    struct sigaction old {};
    ::sigaction(sig, nullptr, &old);
    if (old.sa_handler == SIG_IGN) continue;  // nohup or a background job: stay ignored
    struct sigaction sa {};
    sa.sa_handler = remove_temporaries_and_reraise;
    sigemptyset(&sa.sa_mask);
    sa.sa_flags = SA_RESETHAND;
    ::sigaction(sig, &sa, nullptr);
  }
}

// Blocks the handled signals for its lifetime.
class SignalsBlocked {
 public:
  SignalsBlocked() {
    sigset_t set;
    sigemptyset(&set);
    for (int sig : kSignals) sigaddset(&set, sig);
    ::pthread_sigmask(SIG_BLOCK, &set, &old_);
  }
  ~SignalsBlocked() { ::pthread_sigmask(SIG_SETMASK, &old_, nullptr); }

 private:
  sigset_t old_;
};

int register_temporary(const std::string& path) {
  for (int i = 0; i < kSlots; ++i)
    if (!g_used[i]) {
      std::memcpy(g_paths[i], path.c_str(), path.size() + 1);
      g_used[i] = 1;
      return i;
    }
  throw std::runtime_error("too many temporary output files at once");
}

// The permissions an ordinary new file gets (0666 minus the umask; mkstemp makes 0600).
mode_t new_file_mode() {
  const mode_t mask = ::umask(0);
  ::umask(mask);
  return 0666 & ~mask;
}

// ---- path checks ----

// Whether `a` and `b` name the same file: equivalent() when both exist (links), else the resolved
// paths.
bool same_file(const std::string& a, const std::string& b) {
  std::error_code ea, eb;
  if (fs::exists(a, ea) && fs::exists(b, eb)) {
    std::error_code e;
    const bool same = fs::equivalent(a, b, e);
    if (!e) return same;
  }
  return fs::weakly_canonical(a, ea) == fs::weakly_canonical(b, eb);
}

std::string folder_of(const fs::path& p) {
  return p.has_parent_path() ? p.parent_path().string() : ".";
}

void check_writable(const OutputFile& o) {
  auto refuse = [&](const std::string& why) {
    throw InputError(o.option, o.option + " " + o.path + ": " + why);
  };
  const fs::path p = o.path;
  std::error_code e;
  if (fs::is_directory(p, e)) refuse("is a folder; name a file in it");
  if (!p.has_filename()) refuse("names a folder; name a file");
  if (fs::exists(p, e) && !fs::is_regular_file(p, e)) refuse("exists and is not a regular file");
  const std::string folder = folder_of(p);
  if (!fs::exists(folder, e)) refuse("the folder " + folder + " does not exist");
  if (!fs::is_directory(folder, e)) refuse(folder + " is not a folder");
}

std::string iso8601_utc(std::time_t t) {
  std::tm tm{};
  ::gmtime_r(&t, &tm);
  char buf[32];
  std::strftime(buf, sizeof buf, "%Y-%m-%dT%H:%M:%SZ", &tm);
  return buf;
}

Provenance& provenance_store() {
  static Provenance p{ROLLNOISE_GIT_VERSION, "", iso8601_utc(std::time(nullptr)), ""};
  return p;
}

}  // namespace

const std::vector<std::string>& case_file_keys() {
  static const std::vector<std::string> keys = {
      "contact.wheel_profile", "contact.rail_profile", "track.file",      "wheel.wheelset",
      "wheel.modes",           "wheel.section",        "wheel.shapes", "track.rail_section", "roughness.rail",       "roughness.wheel", "excitation.file"};
  return keys;
}

std::vector<InputFile> case_input_files(const CaseReader& r) {
  std::vector<InputFile> in = {{"the case file", r.source()}};
  for (const std::string& key : case_file_keys()) {
    std::string path;
    try {
      path = key == "excitation.file" ? excitation_file_path(r) : find_model_file(r, key);
    } catch (const InputError&) {
      continue;  // not given (no default): nothing is read
    }
    std::error_code e;
    if (!path.empty() && fs::is_regular_file(path, e)) in.push_back({key, path});
  }
  return in;
}

void check_outputs(const std::vector<OutputFile>& outputs, const std::vector<InputFile>& inputs) {
  for (std::size_t i = 0; i < outputs.size(); ++i) {
    const OutputFile& o = outputs[i];
    check_writable(o);
    // the folder takes a new file (access() says yes to root even on a read-only or pseudo file
    // system); the probe is removed at once
    TemporaryFile(o.path, o.option);
    for (const InputFile& in : inputs)
      if (same_file(o.path, in.path))
        throw InputError(o.option, o.option + " " + o.path + ": is an input of this run (" +
                                       in.what + " " + in.path + "); choose another output name");
    for (std::size_t j = 0; j < i; ++j)
      if (same_file(o.path, outputs[j].path))
        throw InputError(o.option, o.option + " " + o.path + ": is also the output of " +
                                       outputs[j].option + "; give each output its own name");
  }
}

TemporaryFile::TemporaryFile(std::string final_path, const std::string& option)
    : final_(std::move(final_path)) {
  const fs::path p = final_;
  const std::string folder = folder_of(p);
  // ".NAME.XXXXXX" adds 8 characters: a NAME near NAME_MAX (255) is shortened in the temporary
  std::string stem = p.filename().string();
  if (stem.size() + 8 > NAME_MAX) stem.resize(NAME_MAX - 8);
  std::string name = (fs::path(folder) / ("." + stem + ".XXXXXX")).string();
  if (name.size() >= kPathMax) throw InputError(option, option + " " + final_ + ": path too long");
  SignalsBlocked blocked;  // the temporary is in the table before a signal can remove the process
  install_handlers();
  const int fd = ::mkstemp(name.data());
  if (fd < 0)
    throw InputError(option, option + " " + final_ + ": cannot create a file in the folder " +
                                 folder + " (" + std::strerror(errno) + ")");
  ::fchmod(fd, new_file_mode());
  ::close(fd);
  temp_ = name;
  try {
    slot_ = register_temporary(temp_);
  } catch (...) {
    ::unlink(temp_.c_str());
    throw;
  }
}

TemporaryFile::TemporaryFile(TemporaryFile&& o) noexcept
    : final_(std::move(o.final_)), temp_(std::move(o.temp_)), slot_(o.slot_) {
  o.slot_ = -1;
}

TemporaryFile::~TemporaryFile() {
  if (slot_ < 0) return;
  SignalsBlocked blocked;
  ::unlink(temp_.c_str());
  g_used[slot_] = 0;
}

void TemporaryFile::commit() {
  if (slot_ < 0) throw std::logic_error("TemporaryFile::commit: already committed");
  SignalsBlocked blocked;
  if (::rename(temp_.c_str(), final_.c_str()) != 0)
    throw std::runtime_error("cannot rename " + temp_ + " to " + final_ + ": " +
                             std::strerror(errno));
  g_used[slot_] = 0;
  slot_ = -1;
}

void write_bytes(const TemporaryFile& t, const std::string& bytes) {
  auto failed = [&](const char* what, int err) {
    throw std::runtime_error("writing " + t.final_path() + " (temporary " + t.path() + "): " + what + ": " +
                             std::strerror(err));
  };
  const int fd = ::open(t.path().c_str(), O_WRONLY | O_TRUNC | O_CLOEXEC);
  if (fd < 0) failed("cannot open", errno);
  for (std::size_t done = 0; done < bytes.size();) {
    const ssize_t n = ::write(fd, bytes.data() + done, bytes.size() - done);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) {
      const int err = n < 0 ? errno : EIO;
      ::close(fd);
      failed("write failed", err);
    }
    done += std::size_t(n);
  }
  if (::fsync(fd) != 0 && errno != EINVAL) {
    const int err = errno;
    ::close(fd);
    failed("fsync failed", err);
  }
  if (::close(fd) != 0) failed("close failed", errno);
}

void sync_file(const std::string& temp, const std::string& final_path) {
  const int fd = ::open(temp.c_str(), O_RDONLY | O_CLOEXEC);
  int err = fd < 0 ? errno : 0;
  if (fd >= 0) {
    if (::fsync(fd) != 0 && errno != EINVAL) err = errno;
    if (::close(fd) != 0 && !err) err = errno;
  }
  if (err)
    throw std::runtime_error("writing " + final_path + " (temporary " + temp + "): " + std::strerror(err));
}

std::string shell_quote(const std::vector<std::string>& args) {
  static const char* plain =
      "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789_-+=/.,:@%^";
  std::string out;
  for (const std::string& a : args) {
    if (!out.empty()) out += ' ';
    if (!a.empty() && a.find_first_not_of(plain) == std::string::npos) {
      out += a;
      continue;
    }
    out += '\'';
    for (char c : a) out += c == '\'' ? std::string("'\\''") : std::string(1, c);
    out += '\'';
  }
  return out;
}

void record_invocation(int argc, const char* const* argv) {
  Provenance& p = provenance_store();
  p.command_line = shell_quote(std::vector<std::string>(argv, argv + argc));
  for (int i = 1; i < argc && p.command.empty(); ++i)
    if (argv[i][0] != '-') p.command = argv[i];
  p.date = iso8601_utc(std::time(nullptr));
}

std::optional<std::string> recorded_command(const std::string& path) {
  const Hdf5Reader file(path);
  if (!file.ok()) return std::nullopt;
  if (auto command = file.attribute("/", "command")) return command;
  const std::optional<std::string> line = file.attribute("/", "command_line");
  if (!line) return std::nullopt;
  std::istringstream words(*line);
  std::string program, command;
  if (!(words >> program >> command)) return std::nullopt;
  return command;
}

const Provenance& provenance() {
  return provenance_store();
}

}  // namespace rollnoise::io
