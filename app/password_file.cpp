#include "app/password_file.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <fstream>

#include "common/core/error.h"

namespace fleetmap {
namespace {

[[noreturn]] void fail(const std::string& what, const std::string& path, int err) {
  const std::string why = err == ELOOP ? "it is a symbolic link" : std::strerror(err);
  throw IoError("cannot " + what + " password file '" + path + "': " + why);
}

}  // namespace

PasswordFileOut::PasswordFileOut(const std::string& path) : path_(path) {
  // O_EXCL: created here, with 0600 & ~umask (no wider than 0600). A symbolic link,
  // even a dangling one, counts as existing and is then refused by O_NOFOLLOW.
  fd_ = ::open(path.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_NOFOLLOW | O_CLOEXEC, 0600);
  if (fd_ >= 0) {
    created_ = true;
  } else if (errno == EEXIST) {
    // O_NONBLOCK: a FIFO planted there must not hang us; the S_ISREG check refuses it.
    fd_ = ::open(path.c_str(), O_WRONLY | O_NOFOLLOW | O_CLOEXEC | O_NONBLOCK);
  }
  if (fd_ < 0) fail("create", path, errno);
  struct stat st {};
  if (::fstat(fd_, &st) != 0) fail("inspect", path, errno);
  if (!S_ISREG(st.st_mode)) {
    ::close(fd_);
    fd_ = -1;
    throw IoError("cannot write password file '" + path + "': expected a regular file");
  }
  // Exactly 0600 whatever the umask took away, and for an existing file before the
  // password goes in.
  if (::fchmod(fd_, 0600) != 0) fail("set the mode of", path, errno);
}

PasswordFileOut::~PasswordFileOut() {
  if (fd_ >= 0) ::close(fd_);
  if (created_ && !written_) ::unlink(path_.c_str());
}

void PasswordFileOut::write(const std::string& password) {
  if (::ftruncate(fd_, 0) != 0) fail("write", path_, errno);
  const std::string text = password + "\n";
  for (size_t done = 0; done < text.size();) {
    const ssize_t n = ::write(fd_, text.data() + done, text.size() - done);
    if (n < 0 && errno == EINTR) continue;
    if (n < 0) fail("write", path_, errno);
    done += static_cast<size_t>(n);
  }
  const int fd = fd_;
  fd_ = -1;
  if (::close(fd) != 0) fail("write", path_, errno);
  written_ = true;
}

void write_password_file(const std::string& path, const std::string& password) {
  PasswordFileOut(path).write(password);
}

std::string read_password_file(const std::string& path) {
  std::ifstream in(path);
  if (!in) fail("read", path, errno);
  std::string pw;
  std::getline(in, pw);
  if (in.bad()) fail("read", path, errno);
  if (!pw.empty() && pw.back() == '\r') pw.pop_back();
  return pw;
}

}  // namespace fleetmap
