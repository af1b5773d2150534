// SPDX-License-Identifier: GPL-3.0-or-later
#include <elastica/errors.h>
#include <elastica/io/atomic_file.h>

#include <pthread.h>
#include <sys/stat.h>
#include <unistd.h>

#include <atomic>
#include <cerrno>
#include <csignal>
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

// The temporaries being written, for removePendingTemporaryFiles (a signal handler reads these
// slots, so they are lock-free atomics; writeAtomically does not nest beyond a few levels).
constexpr int kPendingSlots = 8;
std::atomic<const char*> gPending[kPendingSlots];
static_assert(std::atomic<const char*>::is_always_lock_free);

// Each step happens before the slot is cleared: a signal between the two finds a file already
// removed or renamed, and unlink fails harmlessly.
int registerPending(const char* path) {
  for (int i = 0; i < kPendingSlots; ++i) {
    const char* expected = nullptr;
    if (gPending[i].compare_exchange_strong(expected, path)) return i;
  }
  return -1;  // not tracked: only a signal in this window could leave the file behind
}

void unregisterPending(int slot) {
  if (slot >= 0) gPending[slot] = nullptr;
}

// A temporary file beside the destination, removed unless committed.
class TempFile {
 public:
  explicit TempFile(const std::string& destination)
      : destination_(destination),
        path_((parentOf(destination) / ("." + fs::path(destination).filename().string() + ".XXXXXX")).string()) {
    const int fd = mkstemp(path_.data());  // fills in path_ (its buffer stays put from here on)
    if (fd < 0) throw IoError(destination + ": cannot create a temporary file beside it (" + std::strerror(errno) + ")");
    slot_ = registerPending(path_.c_str());
    // mkstemp creates the file 0600; give it the permissions a plain fopen would have.
    const mode_t mask = umask(0);
    umask(mask);
    fchmod(fd, 0666 & ~mask);
    close(fd);
  }
  ~TempFile() {
    if (!committed_) std::remove(path_.c_str());
    unregisterPending(slot_);
  }
  TempFile(const TempFile&) = delete;
  TempFile& operator=(const TempFile&) = delete;

  const std::string& path() const { return path_; }
  void commit() {
    if (std::rename(path_.c_str(), destination_.c_str()) != 0)
      throw IoError(destination_ + ": cannot replace it (" + std::strerror(errno) + ")");
    committed_ = true;
    unregisterPending(slot_);
    slot_ = -1;
  }

 private:
  std::string destination_, path_;
  bool committed_ = false;
  int slot_ = -1;
};

const char* gProgram = "elastica";
bool gStderrIsTerminal = false;  // then a progress line may be open: start the message on a new line

// write(2) of a C string (async-signal-safe, unlike stdio).
void say(const char* s) {
  std::size_t n = 0;
  while (s[n]) ++n;
  while (n > 0) {
    const ssize_t w = ::write(STDERR_FILENO, s, n);
    if (w <= 0) return;
    s += w;
    n -= static_cast<std::size_t>(w);
  }
}

extern "C" void onInterrupt(int sig) {
  const int saved = errno;
  const int removed = removePendingTemporaryFiles();
  if (gStderrIsTerminal) say("\n");
  say(gProgram);
  say(sig == SIGINT ? ": interrupted by SIGINT" : sig == SIGTERM ? ": interrupted by SIGTERM" : ": interrupted by SIGHUP");
  say(removed ? "; removed the unfinished output, the destination is untouched\n" : "\n");
  errno = saved;
  // Die of the signal itself: restore the default action, unblock the signal (blocked while its
  // handler runs) and raise it again.
  std::signal(sig, SIG_DFL);
  sigset_t set;
  sigemptyset(&set);
  sigaddset(&set, sig);
  pthread_sigmask(SIG_UNBLOCK, &set, nullptr);
  std::raise(sig);
}

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

int removePendingTemporaryFiles() noexcept {
  int removed = 0;
  for (auto& slot : gPending) {
    const char* path = slot.load();
    if (path && ::unlink(path) == 0) ++removed;
  }
  return removed;
}

void installInterruptHandlers(const char* program) {
  gProgram = program;
  gStderrIsTerminal = isatty(STDERR_FILENO);
  for (int sig : {SIGINT, SIGTERM, SIGHUP}) {
    struct sigaction old {};
    if (sigaction(sig, nullptr, &old) == 0 && old.sa_handler == SIG_IGN) continue;
    struct sigaction sa {};
    sa.sa_handler = onInterrupt;
    sigemptyset(&sa.sa_mask);
    // Block the other two while one is handled: one cleanup, one message.
    for (int other : {SIGINT, SIGTERM, SIGHUP}) sigaddset(&sa.sa_mask, other);
    sigaction(sig, &sa, nullptr);
  }
}

}  // namespace elastica::io
