#include <elastica/errors.h>
#include <elastica/io/atomic_file.h>

#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>

namespace elastica::io {
namespace fs = std::filesystem;

namespace {

fs::path parentOf(const std::string& path) {
  const fs::path parent = fs::path(path).parent_path();
  return parent.empty() ? fs::path(".") : parent;
}

// A temporary file beside the destination, removed unless committed.
class TempFile {
 public:
  explicit TempFile(const std::string& destination) : destination_(destination) {
    std::string pattern = (parentOf(destination) / ("." + fs::path(destination).filename().string() + ".XXXXXX")).string();
    const int fd = mkstemp(pattern.data());
    if (fd < 0) throw IoError(destination + ": cannot create a temporary file beside it (" + std::strerror(errno) + ")");
    // mkstemp creates the file 0600; give it the permissions a plain fopen would have.
    const mode_t mask = umask(0);
    umask(mask);
    fchmod(fd, 0666 & ~mask);
    close(fd);
    path_ = pattern;
  }
  ~TempFile() {
    if (!committed_) std::remove(path_.c_str());
  }
  TempFile(const TempFile&) = delete;
  TempFile& operator=(const TempFile&) = delete;

  const std::string& path() const { return path_; }
  void commit() {
    if (std::rename(path_.c_str(), destination_.c_str()) != 0)
      throw IoError(destination_ + ": cannot replace it (" + std::strerror(errno) + ")");
    committed_ = true;
  }

 private:
  std::string destination_, path_;
  bool committed_ = false;
};

}  // namespace

void checkOutputPath(const std::string& output, const std::string& input) {
  if (output.empty()) throw IoError("output path is empty");
  std::error_code ec;
  if (fs::is_directory(output, ec)) throw IoError(output + ": is a directory, not an output file");
  const fs::path dir = parentOf(output);
  if (!fs::is_directory(dir, ec)) throw IoError(output + ": output directory '" + dir.string() + "' does not exist");
  if (access(dir.c_str(), W_OK) != 0) throw IoError(output + ": output directory '" + dir.string() + "' is not writable");
  if (!input.empty() && fs::exists(output, ec) && fs::equivalent(input, output, ec))
    throw IoError(output + ": output would overwrite the input file; choose another name");
}

void writeAtomically(const std::string& path, const std::function<void(const std::string&)>& write) {
  checkOutputPath(path);
  TempFile tmp(path);
  write(tmp.path());
  tmp.commit();
}

}  // namespace elastica::io
