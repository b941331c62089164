#include "talus/run/output_folder.hpp"

#include <fcntl.h>
#include <fmt/format.h>
#include <sys/file.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <charconv>
#include <cstdint>
#include <cstring>
#include <fstream>
#include <set>
#include <system_error>
#include <vector>

#include "talus/core/error.hpp"
#include "talus/io/archive.hpp"

namespace talus::run {
namespace fs = std::filesystem;

namespace {

constexpr const char* kRecord = ".talus-run";
constexpr const char* kLock = ".talus-lock";
// Space held back while the run writes, given up when it fails, so that the
// summary saying why still fits on a disk the run filled (a summary is a few
// kB, with the resolved scenario).
constexpr const char* kReserve = ".talus-reserve";
constexpr std::size_t kReserveBytes = 64 * 1024;
constexpr const char* kRunning = "talus run folder: running";
constexpr const char* kFinished = "talus run folder: finished";

bool is_own(const std::string& name) {
  return name == kRecord || name == kLock || name == kReserve;
}

// Best effort: on a disk already full there is nothing to hold back.
void reserve_space(const fs::path& out) {
  std::ofstream file(out / kReserve, std::ios::binary | std::ios::trunc);
  const std::string block(kReserveBytes, '\0');
  file.write(block.data(), static_cast<std::streamsize>(block.size()));
  file.flush();
}

constexpr const char* kScenario = "scenario ";
constexpr const char* kThreads = "threads ";

// What `.talus-run` says: whether the run finished, the checksum of the
// scenario.toml it started from, the thread count it last ran on, and the
// entries it wrote. Line 1 the state, line 2 "scenario <checksum>" ("scenario
// -" before one is written), line 3 "threads <n>" (absent in folders of older
// talus), then one entry per line.
struct Record {
  bool present = false, finished = false;
  std::string scenario = "-";
  int threads = 0;  // 0: not recorded
  std::set<std::string> entries;
};

Record read_record(const fs::path& out) {
  Record r;
  std::ifstream in(out / kRecord);
  if (!in) return r;
  r.present = true;
  std::string line;
  std::getline(in, line);
  r.finished = line == kFinished;
  if (std::getline(in, line) && line.starts_with(kScenario))
    r.scenario = line.substr(std::string(kScenario).size());
  else if (!line.empty())
    r.entries.insert(line);
  if (std::getline(in, line) && line.starts_with(kThreads)) {
    int n = 0;
    const char *first = line.data() + std::string(kThreads).size(),
               *last = line.data() + line.size();
    const auto [end, ec] = std::from_chars(first, last, n);
    r.threads = ec == std::errc() && end == last && n > 0 ? n : 0;
  } else if (!line.empty()) {
    r.entries.insert(line);
  }
  while (std::getline(in, line))
    if (!line.empty()) r.entries.insert(line);
  return r;
}

// Writes the record through a temporary file and a rename, so that a reader
// sees the old record or the new one, never half of one.
void write_record(const fs::path& out, bool finished, const std::string& scenario, int threads) {
  std::vector<std::string> entries;
  std::error_code ec;
  if (finished)
    for (const auto& e : fs::directory_iterator(out, ec)) {
      const std::string name = e.path().filename().string();
      if (!is_own(name) && name != std::string(kRecord) + ".tmp") entries.push_back(name);
    }
  std::sort(entries.begin(), entries.end());
  std::string text = fmt::format("{}\n{}{}\n{}{}\n", finished ? kFinished : kRunning, kScenario,
                                 scenario, kThreads, threads);
  for (const auto& e : entries) text += e + '\n';
  // Whole or not at all (a full disk once left it empty): temporary file, then rename.
  try {
    io::write_file_atomically(out / kRecord, text);
  } catch (const RunError& e) {
    throw InputError(
        fmt::format("{}: cannot record the run in its folder: {}", out.string(), e.what()));
  }
}

// FNV-1a of scenario.toml ("-" when there is none): enough to see an edit.
std::string scenario_checksum(const fs::path& out) {
  std::ifstream in(out / "scenario.toml", std::ios::binary);
  if (!in) return "-";
  std::uint64_t h = 1469598103934665603ull;
  for (char c; in.get(c);) h = (h ^ static_cast<unsigned char>(c)) * 1099511628211ull;
  return fmt::format("{:016x}", h);
}

// Takes the folder's lock, or refuses when another run holds it.
int lock(const fs::path& out) {
  const fs::path path = out / kLock;
  const int fd = ::open(path.c_str(), O_RDWR | O_CREAT | O_CLOEXEC, 0644);
  if (fd < 0)
    throw InputError(fmt::format("{}: cannot write in the output folder ({})", out.string(),
                                 std::strerror(errno)));
  if (::flock(fd, LOCK_EX | LOCK_NB) != 0) {
    ::close(fd);
    throw InputError(fmt::format(
        "{}: another talus run is writing in this folder; wait for it or choose another --out",
        out.string()));
  }
  return fd;
}

// Refuses --force on a folder unless everything in it is talus's own.
void check_own_folder(const fs::path& out, const Record& record) {
  const std::string refuse = "--force removes only the files of a talus run";
  if (!record.present)
    throw InputError(fmt::format(
        "{}: not a talus run folder (no {}); {}: remove it yourself or choose another --out",
        out.string(), kRecord, refuse));
  if (!record.finished)
    throw InputError(fmt::format(
        "{}: left by a run that did not finish, so talus cannot tell its files from others; "
        "resume it with --resume, or remove it yourself",
        out.string()));
  for (const auto& e : fs::directory_iterator(out)) {
    const std::string name = e.path().filename().string();
    if (!is_own(name) && !record.entries.count(name))
      throw InputError(
          fmt::format("{}: holds '{}', which talus did not write; {}: move it or "
                      "choose another --out",
                      out.string(), name, refuse));
  }
}

bool holds_others(const fs::path& out) {
  for (const auto& e : fs::directory_iterator(out))
    if (!is_own(e.path().filename().string())) return true;
  return false;
}

}  // namespace

OutputFolder OutputFolder::claim(const fs::path& out, bool force, int threads) {
  if (fs::exists(out) && !fs::is_directory(out))
    throw InputError(out.string() + ": output path exists and is not a folder");
  // Everything is checked before the folder is touched.
  const bool full = fs::exists(out) && holds_others(out);
  if (full && !force)
    throw InputError(out.string() +
                     ": output folder exists and is not empty; use --force to overwrite it or "
                     "--out to choose another");
  if (full) check_own_folder(out, read_record(out));
  const bool existed = fs::exists(out);
  std::error_code ec;
  fs::create_directories(out, ec);
  if (ec)
    throw InputError(
        fmt::format("{}: cannot create the output folder ({}); choose another with --out",
                    out.string(), ec.message()));
  OutputFolder folder(out, lock(out));
  folder.created_ = !existed;
  folder.threads_ = threads;
  // Read again under the lock: the run that wrote it may have finished since.
  if (full) {
    const Record record = read_record(out);
    check_own_folder(out, record);
    for (const auto& name : record.entries) fs::remove_all(out / name);
  }
  write_record(out, false, folder.scenario_, folder.threads_);
  folder.recording_ = true;
  reserve_space(out);
  return folder;
}

int OutputFolder::recorded_threads(const fs::path& out) { return read_record(out).threads; }

OutputFolder OutputFolder::reopen(const fs::path& out, int threads) {
  OutputFolder folder(out, lock(out));
  folder.threads_ = threads;
  const Record record = read_record(out);
  folder.scenario_ = scenario_checksum(out);
  if (record.scenario != "-" && record.scenario != folder.scenario_)
    throw InputError(fmt::format(
        "{}: scenario.toml was changed after the run started; a resumed run continues the "
        "scenario it started with: restore the file, or start a new run from the changed one",
        (out / "scenario.toml").string()));
  write_record(out, false, folder.scenario_, folder.threads_);
  folder.recording_ = true;
  reserve_space(out);
  return folder;
}

void OutputFolder::free_reserve() noexcept {
  std::error_code ec;
  if (lock_ >= 0) fs::remove(path_ / kReserve, ec);
}

void OutputFolder::scenario_written() {
  scenario_ = scenario_checksum(path_);
  write_record(path_, false, scenario_, threads_);
}

OutputFolder::OutputFolder(OutputFolder&& other) noexcept
    : path_(std::move(other.path_)),
      lock_(other.lock_),
      recording_(other.recording_),
      scenario_(std::move(other.scenario_)),
      threads_(other.threads_),
      created_(other.created_) {
  other.lock_ = -1;
}

OutputFolder& OutputFolder::operator=(OutputFolder&& other) noexcept {
  if (this != &other) {
    release();
    path_ = std::move(other.path_);
    lock_ = other.lock_;
    recording_ = other.recording_;
    scenario_ = std::move(other.scenario_);
    threads_ = other.threads_;
    created_ = other.created_;
    other.lock_ = -1;
  }
  return *this;
}

OutputFolder::~OutputFolder() { release(); }

void OutputFolder::discard() noexcept {
  if (lock_ < 0) return;
  // Everything here is this run's: claim() found the folder empty of other
  // files or emptied it of a finished run's.
  std::error_code ec;
  for (const auto& e : fs::directory_iterator(path_, ec)) fs::remove_all(e.path(), ec);
  recording_ = false;
  release();
  if (created_) fs::remove(path_, ec);
}

void OutputFolder::release() noexcept {
  if (lock_ < 0) return;
  free_reserve();
  try {
    if (recording_) write_record(path_, true, scenario_, threads_);
  } catch (...) {
    // The record serves a later --force only; a run that cannot write it has
    // already reported why it could not write.
  }
  ::flock(lock_, LOCK_UN);
  ::close(lock_);
  lock_ = -1;
}

void check_run_name(const std::string& name, const std::string& where) {
  const bool plain =
      !name.empty() && name.front() != '.' && std::all_of(name.begin(), name.end(), [](char c) {
        return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') ||
               c == '-' || c == '_' || c == '.';
      });
  if (!plain)
    throw InputError(fmt::format(
        "{} 'name': expected a plain name (letters, digits, '-', '_', '.'; not starting with "
        "'.'), got \"{}\": it becomes the folder runs/<name>; use --out to write elsewhere",
        where, name));
}

}  // namespace talus::run
