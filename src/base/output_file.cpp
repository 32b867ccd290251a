#include "base/output_file.h"

#include <fcntl.h>
#include <signal.h>
#include <sys/stat.h>
#include <unistd.h>

#include <atomic>
#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>

#include "base/error.h"
#include "base/input_files.h"

namespace objektiv {

namespace {
namespace fs = std::filesystem;

// The temporary file being written, for RemovePendingTemporaryFile (no allocation there).
char pending_path[4096];
std::atomic<bool> pending{false};

// Where `path` is written: a symbolic link's target, else the path itself.
fs::path Target(const std::string& path) {
  std::error_code ec;
  if (!fs::is_symlink(path, ec)) return path;
  fs::path t = fs::weakly_canonical(path, ec);
  return ec ? fs::path(path) : t;
}

fs::path DirectoryOf(const fs::path& target) {
  return target.has_parent_path() ? target.parent_path() : fs::path(".");
}

// This machine's name (temporaries on a shared folder say whose they are).
const std::string& HostName() {
  static const std::string name = [] {
    char buf[256] = {};
    if (gethostname(buf, sizeof buf - 1) != 0 || !buf[0]) return std::string("host");
    std::string n(buf);
    for (char& c : n)
      if (c == '/' || c == '-') c = '_';
    return n;
  }();
  return name;
}

// A new, empty file beside `target` (O_EXCL: never an existing one), open for writing.
std::pair<fs::path, int> MakeTemporary(const std::string& path, const fs::path& target) {
  static std::atomic<unsigned> counter{0};
  for (;;) {
    fs::path temp = DirectoryOf(target) / fmt::format(".{}.{}-{}-{}.tmp", target.filename().string(), HostName(),
                                                      getpid(), counter.fetch_add(1));
    int fd = open(temp.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0666);
    if (fd >= 0) return {temp, fd};
    if (errno != EEXIST)
      throw InputError(fmt::format("{}: cannot create a file in '{}': {}", path, DirectoryOf(target).string(),
                                   std::strerror(errno)));
  }
}

// What forbids replacing an existing `target`: a directory, a read-only file, an input.
void CheckReplaceable(const std::string& path, const fs::path& target) {
  if (std::optional<std::string> input = InputFileAt(target.string()))
    throw InputError(fmt::format("{}: refusing to overwrite {}, an input file of this run", path, *input));
  std::error_code ec;
  fs::file_status st = fs::status(target, ec);
  if (fs::is_directory(st)) throw InputError(fmt::format("{}: is a directory", path));
  if (fs::exists(st) && access(target.c_str(), W_OK) != 0 && errno == EACCES)
    throw InputError(fmt::format("{}: the file is read-only; refusing to replace it", path));
}

void Fsync(const fs::path& p) {
  int fd = open(p.c_str(), O_RDONLY | O_CLOEXEC);
  if (fd < 0) return;
  fsync(fd);
  close(fd);
}
}  // namespace

void CheckOutputFile(const std::string& path) {
  const fs::path target = Target(path);
  const fs::path dir = DirectoryOf(target);
  std::error_code ec;
  fs::file_status st = fs::status(dir, ec);
  if (!fs::exists(st)) throw InputError(fmt::format("{}: the directory '{}' does not exist", path, dir.string()));
  if (!fs::is_directory(st)) throw InputError(fmt::format("{}: '{}' is not a directory", path, dir.string()));
  CheckReplaceable(path, target);
  auto [temp, fd] = MakeTemporary(path, target);
  close(fd);
  unlink(temp.c_str());
}

void WriteFileAtomically(const std::string& path, const std::function<void(const std::string& temp)>& fill) {
  const fs::path target = Target(path);
  CheckReplaceable(path, target);
  auto [temp, fd] = MakeTemporary(path, target);
  struct stat old;
  if (stat(target.c_str(), &old) == 0) fchmod(fd, old.st_mode & 07777);  // keep the replaced file's mode
  close(fd);
  if (temp.native().size() < sizeof(pending_path)) {
    std::memcpy(pending_path, temp.c_str(), temp.native().size() + 1);
    pending = true;
  }
  try {
    fill(temp.string());
    Fsync(temp);
    if (rename(temp.c_str(), target.c_str()) != 0)
      throw InputError(fmt::format("{}: cannot replace the file: {}", path, std::strerror(errno)));
  } catch (...) {
    pending = false;
    unlink(temp.c_str());
    throw;
  }
  pending = false;
  Fsync(DirectoryOf(target));  // the rename itself survives a crash
}

void WriteTextFileAtomically(const std::string& path, std::string_view text) {
  WriteFileAtomically(path, [&](const std::string& temp) {
    std::ofstream out(temp, std::ios::binary | std::ios::trunc);
    out.write(text.data(), std::streamsize(text.size()));
    out.close();
    if (!out) throw InputError(fmt::format("{}: cannot write the file: {}", path, std::strerror(errno)));
  });
}

void RemovePendingTemporaryFile() {
  if (pending.load()) unlink(pending_path);
}

void RemoveStaleTemporaries(const std::string& path) {
  const fs::path target = Target(path);
  // (Built by appending: GCC 12 warns falsely of an overlapping copy in "." + std::string&&.)
  std::string prefix = ".";
  prefix += target.filename().string();
  prefix += '.';
  prefix += HostName();
  prefix += '-';
  std::error_code ec;
  for (const fs::directory_entry& e : fs::directory_iterator(DirectoryOf(target), ec)) {
    const std::string name = e.path().filename().string();
    if (name.size() <= prefix.size() + 4 || name.compare(0, prefix.size(), prefix) != 0 ||
        name.compare(name.size() - 4, 4, ".tmp") != 0)
      continue;
    const long pid = std::strtol(name.c_str() + prefix.size(), nullptr, 10);
    if (pid > 0 && pid != getpid() && kill(pid_t(pid), 0) != 0 && errno == ESRCH) fs::remove(e.path(), ec);
  }
}

}  // namespace objektiv
