#pragma once
// A real browser for tests: headless Chromium as a child process and a minimal Chrome
// DevTools Protocol client (https://chromedevtools.github.io/devtools-protocol/) over
// its WebSocket, synchronous: each command waits for its own result by id; events are
// kept for wait_event.
#include <sys/types.h>

#include <chrono>
#include <deque>
#include <memory>
#include <optional>
#include <stdexcept>
#include <string>

#include <nlohmann/json.hpp>

namespace fleetmap::test {

// `chromium --headless=new --remote-debugging-port=0` on a fresh profile; the port it
// chose is read from <profile>/DevToolsActivePort. The destructor kills it (its whole
// process group) and removes the profile. Throws std::runtime_error with a clear message
// when chromium is not installed (scripts/setup.sh installs it) or does not start.
class Chromium {
 public:
  explicit Chromium(const std::string& log_path, int width = 1280, int height = 800);
  ~Chromium();
  Chromium(const Chromium&) = delete;
  Chromium& operator=(const Chromium&) = delete;

  unsigned short port() const { return port_; }
  std::string log() const;

  // The executable: $FLEETMAP_CHROMIUM, else chromium or chromium-browser on PATH; empty
  // when there is none.
  static std::string find_executable();

 private:
  std::string profile_;
  std::string log_path_;
  pid_t pid_ = -1;
  unsigned short port_ = 0;
};

struct CdpError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

// One page target of a running Chromium.
class CdpPage {
 public:
  explicit CdpPage(unsigned short port, std::chrono::milliseconds timeout = std::chrono::seconds(15));
  ~CdpPage();
  CdpPage(const CdpPage&) = delete;
  CdpPage& operator=(const CdpPage&) = delete;

  // Sends {"id", "method", "params"} and returns the result; throws CdpError on the
  // protocol's error or when no answer comes in time.
  nlohmann::json call(const std::string& method, const nlohmann::json& params = nlohmann::json::object());

  // The next event named method (already received or arriving within timeout).
  nlohmann::json wait_event(const std::string& method, std::chrono::milliseconds timeout);

  // Runtime.evaluate with awaitPromise and returnByValue: the expression's value as JSON;
  // throws CdpError with the page's exception text when it threw.
  nlohmann::json evaluate(const std::string& expression);

  // Polls expression (truthy) every 100 ms until timeout; false when it never held.
  bool wait_for(const std::string& expression, std::chrono::milliseconds timeout);

  void navigate(const std::string& url);  // and waits for document.readyState "complete"
  void click(double x, double y);         // mouse moved, pressed, released (left button)
  void click_element(const std::string& css_selector);  // at the centre of its box
  void insert_text(const std::string& text);            // into the focused element
  std::string screenshot_png();                         // the viewport, as PNG bytes

  // The page's uncaught exceptions and console.error lines seen so far (for a failing
  // test's message).
  std::string page_errors() const;

  void set_timeout(std::chrono::milliseconds t) { timeout_ = t; }

 private:
  struct Connection;
  std::unique_ptr<Connection> c_;
  std::chrono::milliseconds timeout_;
  long long next_id_ = 1;
  std::deque<nlohmann::json> events_;
  // One message, or nullopt when nothing came before the deadline.
  std::optional<nlohmann::json> read_message(std::chrono::steady_clock::time_point deadline);
};

}  // namespace fleetmap::test
