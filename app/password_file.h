#pragma once
// Password files: a generated robot password handed to whoever installs the robot
// (`fleetmap robot add --password-out`), and the --password-file every program reads.
#include <string>

namespace fleetmap {

// A password file opened before the password exists, so that a path that cannot take
// it fails before a robot account is created with a password nobody would know.
//   * mode 0600 from the moment the file exists: a new file is created with 0600
//     (whatever the umask); an existing one is set to 0600 before anything is written;
//   * a symbolic link is refused (O_NOFOLLOW: no writing through a planted link), and
//     anything but a regular file;
//   * write() replaces the old content; a file created here and never written is
//     removed again, an existing one is left as it was.
// Throws IoError naming the file and the system's reason.
class PasswordFileOut {
 public:
  explicit PasswordFileOut(const std::string& path);
  PasswordFileOut(const PasswordFileOut&) = delete;
  PasswordFileOut& operator=(const PasswordFileOut&) = delete;
  ~PasswordFileOut();

  void write(const std::string& password);  // the password and a line end

 private:
  std::string path_;
  int fd_ = -1;
  bool created_ = false, written_ = false;
};

// PasswordFileOut(path).write(password).
void write_password_file(const std::string& path, const std::string& password);

// The first line of path, without its line end ("\n" or "\r\n"). Throws IoError.
std::string read_password_file(const std::string& path);

}  // namespace fleetmap
