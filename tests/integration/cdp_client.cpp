#include "tests/integration/cdp_client.h"

#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <thread>
#include <vector>

#include <boost/asio/connect.hpp>
#include <boost/asio/ip/tcp.hpp>
#include <boost/beast/core.hpp>
#include <boost/beast/http.hpp>
#include <boost/beast/websocket.hpp>

namespace fleetmap::test {

namespace beast = boost::beast;
namespace http = beast::http;
namespace websocket = beast::websocket;
namespace net = boost::asio;
using tcp = net::ip::tcp;
using Clock = std::chrono::steady_clock;

namespace {

std::string slurp(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

bool executable(const std::string& path) { return !path.empty() && ::access(path.c_str(), X_OK) == 0; }

std::string base64_decode(const std::string& in) {
  auto value = [](char c) -> int {
    if (c >= 'A' && c <= 'Z') return c - 'A';
    if (c >= 'a' && c <= 'z') return c - 'a' + 26;
    if (c >= '0' && c <= '9') return c - '0' + 52;
    if (c == '+') return 62;
    if (c == '/') return 63;
    return -1;
  };
  std::string out;
  out.reserve(in.size() * 3 / 4);
  unsigned bits = 0;
  int count = 0;
  for (char c : in) {
    const int v = value(c);
    if (v < 0) continue;  // '=' padding, line breaks
    bits = (bits << 6) | static_cast<unsigned>(v);
    count += 6;
    if (count >= 8) {
      count -= 8;
      out.push_back(static_cast<char>((bits >> count) & 0xFF));
    }
  }
  return out;
}

// GET (or PUT) http://127.0.0.1:port<target>: the body.
std::string http_get(unsigned short port, const std::string& target, http::verb verb = http::verb::get) {
  net::io_context ioc;
  tcp::socket socket(ioc);
  socket.connect(tcp::endpoint(net::ip::make_address("127.0.0.1"), port));
  http::request<http::empty_body> req(verb, target, 11);
  req.set(http::field::host, "127.0.0.1:" + std::to_string(port));
  http::write(socket, req);
  beast::flat_buffer buffer;
  http::response<http::string_body> res;
  http::read(socket, buffer, res);
  beast::error_code ec;
  socket.shutdown(tcp::socket::shutdown_both, ec);
  if (res.result() != http::status::ok)
    throw CdpError("DevTools " + std::string(http::to_string(verb)) + " " + target + ": HTTP " +
                   std::to_string(res.result_int()));
  return res.body();
}

}  // namespace

// ---- Chromium ------------------------------------------------------------------------

std::string Chromium::find_executable() {
  if (const char* env = std::getenv("FLEETMAP_CHROMIUM"); env && executable(env)) return env;
  const char* path = std::getenv("PATH");
  std::istringstream dirs(path ? path : "/usr/bin:/bin");
  for (std::string dir; std::getline(dirs, dir, ':');) {
    for (const char* name : {"chromium", "chromium-browser"}) {
      const std::string candidate = dir + "/" + name;
      if (executable(candidate)) return candidate;
    }
  }
  return "";
}

Chromium::Chromium(const std::string& log_path, int width, int height) : log_path_(log_path) {
  const std::string exe = find_executable();
  if (exe.empty())
    throw std::runtime_error(
        "chromium is not installed (no chromium or chromium-browser on PATH, FLEETMAP_CHROMIUM unset): "
        "run scripts/setup.sh, which installs it");
  char dir[] = "/tmp/fleetmap-chromium-XXXXXX";
  if (!::mkdtemp(dir)) throw std::runtime_error("mkdtemp failed for the chromium profile");
  profile_ = dir;

  std::vector<std::string> args = {exe,
                                   "--headless=new",
                                   "--no-sandbox",
                                   "--disable-gpu",
                                   "--remote-debugging-port=0",
                                   "--user-data-dir=" + profile_,
                                   "--window-size=" + std::to_string(width) + "," + std::to_string(height),
                                   "--no-first-run",
                                   "--no-default-browser-check",
                                   "--disable-extensions",
                                   "--disable-background-networking",
                                   "--disable-dev-shm-usage",
                                   "--hide-scrollbars",
                                   "about:blank"};
  pid_ = fork();
  if (pid_ < 0) throw std::runtime_error("fork failed for chromium");
  if (pid_ == 0) {
    setpgid(0, 0);  // its own group: the destructor ends the renderers and helpers too
    if (FILE* f = std::freopen(log_path_.c_str(), "a", stdout)) (void)f;
    dup2(fileno(stdout), fileno(stderr));
    std::vector<char*> argv;
    for (auto& a : args) argv.push_back(a.data());
    argv.push_back(nullptr);
    execv(exe.c_str(), argv.data());
    _exit(127);
  }
  setpgid(pid_, pid_);

  // DevToolsActivePort: the port on the first line, the browser's path on the second.
  const std::string port_file = profile_ + "/DevToolsActivePort";
  const auto until = Clock::now() + std::chrono::seconds(30);
  while (Clock::now() < until) {
    int status = 0;
    if (waitpid(pid_, &status, WNOHANG) == pid_) {
      pid_ = -1;
      throw std::runtime_error("chromium exited at start (" + exe + "); its log:\n" + log());
    }
    std::istringstream lines(slurp(port_file));
    unsigned port = 0;
    if (lines >> port && port > 0 && port < 65536) {
      port_ = static_cast<unsigned short>(port);
      return;
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(50));
  }
  throw std::runtime_error("chromium wrote no " + port_file + " within 30 s; its log:\n" + log());
}

Chromium::~Chromium() {
  if (pid_ > 0) {
    ::kill(-pid_, SIGTERM);
    int status = 0;
    const auto until = Clock::now() + std::chrono::seconds(5);
    while (waitpid(pid_, &status, WNOHANG) == 0) {
      if (Clock::now() >= until) {
        ::kill(-pid_, SIGKILL);
        waitpid(pid_, &status, 0);
        break;
      }
      std::this_thread::sleep_for(std::chrono::milliseconds(50));
    }
    ::kill(-pid_, SIGKILL);  // helpers that outlived the browser
  }
  std::error_code ec;
  if (!profile_.empty()) std::filesystem::remove_all(profile_, ec);
}

std::string Chromium::log() const { return slurp(log_path_); }

// ---- CdpPage ---------------------------------------------------------------------------

// One read is kept outstanding across calls, so that a wait that times out leaves the
// WebSocket intact (cancelling a Beast read would close it).
struct CdpPage::Connection {
  net::io_context ioc;
  websocket::stream<beast::tcp_stream> ws{ioc};
  beast::flat_buffer buffer;
  bool reading = false;
  bool read_done = false;
  beast::error_code read_ec;

  void start_read() {
    reading = true;
    ws.async_read(buffer, [this](beast::error_code ec, std::size_t) {
      read_ec = ec;
      read_done = true;
      reading = false;
    });
  }

  // Runs handlers until done() or the deadline; false on the deadline.
  template <class Done>
  bool run_until(Done done, Clock::time_point deadline) {
    while (!done()) {
      if (ioc.stopped()) ioc.restart();
      if (ioc.run_one_until(deadline) == 0 && Clock::now() >= deadline) return done();
    }
    return true;
  }
};

CdpPage::CdpPage(unsigned short port, std::chrono::milliseconds timeout)
    : c_(std::make_unique<Connection>()), timeout_(timeout) {
  // The first page target (Chromium opened about:blank), else a new one.
  std::string ws_url;
  const auto until = Clock::now() + timeout_;
  while (ws_url.empty()) {
    for (const auto& t : nlohmann::json::parse(http_get(port, "/json/list")))
      if (t.value("type", "") == "page" && t.contains("webSocketDebuggerUrl")) {
        ws_url = t["webSocketDebuggerUrl"].get<std::string>();
        break;
      }
    if (ws_url.empty() && Clock::now() >= until) {
      // Chromium takes /json/new only as PUT.
      const auto t = nlohmann::json::parse(http_get(port, "/json/new?about:blank", http::verb::put));
      ws_url = t.at("webSocketDebuggerUrl").get<std::string>();
    }
    if (ws_url.empty()) std::this_thread::sleep_for(std::chrono::milliseconds(100));
  }
  // ws://127.0.0.1:PORT/devtools/page/ID
  const auto scheme = ws_url.find("://");
  const auto slash = ws_url.find('/', scheme + 3);
  if (scheme == std::string::npos || slash == std::string::npos) throw CdpError("odd webSocketDebuggerUrl " + ws_url);
  const std::string host = ws_url.substr(scheme + 3, slash - scheme - 3);

  auto& stream = beast::get_lowest_layer(c_->ws);
  stream.expires_after(timeout_);
  stream.connect(tcp::endpoint(net::ip::make_address("127.0.0.1"), port));
  stream.expires_never();
  c_->ws.read_message_max(64 << 20);  // screenshots arrive as one base64 message
  c_->ws.handshake(host, ws_url.substr(slash));
  call("Page.enable");
  call("Runtime.enable");
}

CdpPage::~CdpPage() {
  beast::error_code ec;
  beast::get_lowest_layer(c_->ws).socket().close(ec);
}

std::optional<nlohmann::json> CdpPage::read_message(Clock::time_point deadline) {
  if (!c_->reading && !c_->read_done) c_->start_read();
  if (!c_->run_until([&] { return c_->read_done; }, deadline)) return std::nullopt;
  c_->read_done = false;
  if (c_->read_ec) throw CdpError("DevTools WebSocket: " + c_->read_ec.message());
  std::string text = beast::buffers_to_string(c_->buffer.data());
  c_->buffer.consume(c_->buffer.size());
  return nlohmann::json::parse(text);
}

nlohmann::json CdpPage::call(const std::string& method, const nlohmann::json& params) {
  const long long id = next_id_++;
  const std::string text = nlohmann::json{{"id", id}, {"method", method}, {"params", params}}.dump();
  const auto deadline = Clock::now() + timeout_;
  bool written = false;
  beast::error_code write_ec;
  c_->ws.text(true);
  c_->ws.async_write(net::buffer(text), [&](beast::error_code ec, std::size_t) {
    write_ec = ec;
    written = true;
  });
  if (!c_->run_until([&] { return written; }, deadline)) throw CdpError(method + ": could not send in time");
  if (write_ec) throw CdpError(method + ": " + write_ec.message());
  for (;;) {
    auto msg = read_message(deadline);
    if (!msg) throw CdpError(method + ": no answer within " + std::to_string(timeout_.count()) + " ms");
    if (msg->contains("id") && (*msg)["id"] == id) {
      if (msg->contains("error")) throw CdpError(method + ": " + (*msg)["error"].dump());
      return msg->value("result", nlohmann::json::object());
    }
    if (msg->contains("method")) {
      events_.push_back(std::move(*msg));
      if (events_.size() > 1000) events_.pop_front();  // nobody waits for old ones
    }
  }
}

nlohmann::json CdpPage::wait_event(const std::string& method, std::chrono::milliseconds timeout) {
  for (auto it = events_.begin(); it != events_.end(); ++it)
    if ((*it)["method"] == method) {
      nlohmann::json e = std::move(*it);
      events_.erase(it);
      return e;
    }
  const auto deadline = Clock::now() + timeout;
  for (;;) {
    auto msg = read_message(deadline);
    if (!msg) throw CdpError("no " + method + " event within " + std::to_string(timeout.count()) + " ms");
    if (msg->value("method", "") == method) return *msg;
    if (msg->contains("method")) events_.push_back(std::move(*msg));
    if (events_.size() > 1000) events_.pop_front();
  }
}

nlohmann::json CdpPage::evaluate(const std::string& expression) {
  const nlohmann::json r =
      call("Runtime.evaluate", {{"expression", expression}, {"awaitPromise", true}, {"returnByValue", true}});
  if (r.contains("exceptionDetails")) {
    const auto& d = r["exceptionDetails"];
    std::string what = d.value("text", "exception");
    if (d.contains("exception") && d["exception"].contains("description"))
      what = d["exception"]["description"].get<std::string>();
    throw CdpError("evaluate threw: " + what + "\n  in: " + expression);
  }
  const auto& result = r.at("result");
  return result.contains("value") ? result["value"] : nlohmann::json();
}

bool CdpPage::wait_for(const std::string& expression, std::chrono::milliseconds timeout) {
  const auto until = Clock::now() + timeout;
  const std::string truthy = "Boolean(" + expression + ")";
  for (;;) {
    if (evaluate(truthy) == true) return true;
    if (Clock::now() >= until) return false;
    std::this_thread::sleep_for(std::chrono::milliseconds(100));
  }
}

void CdpPage::navigate(const std::string& url) {
  events_.clear();  // a load event of an earlier page must not count
  const nlohmann::json r = call("Page.navigate", {{"url", url}});
  if (r.contains("errorText") && !r["errorText"].get<std::string>().empty())
    throw CdpError("navigate " + url + ": " + r["errorText"].get<std::string>());
  wait_event("Page.loadEventFired", timeout_);
}

void CdpPage::click(double x, double y) {
  call("Input.dispatchMouseEvent", {{"type", "mouseMoved"}, {"x", x}, {"y", y}});
  for (const char* type : {"mousePressed", "mouseReleased"})
    call("Input.dispatchMouseEvent",
         {{"type", type}, {"x", x}, {"y", y}, {"button", "left"}, {"buttons", 1}, {"clickCount", 1}});
}

void CdpPage::click_element(const std::string& css_selector) {
  const nlohmann::json at = evaluate("(() => { const e = document.querySelector(" + nlohmann::json(css_selector).dump() +
                                     "); if (!e) return null; e.scrollIntoView({block: 'center'});"
                                     " const r = e.getBoundingClientRect();"
                                     " return [r.left + r.width / 2, r.top + r.height / 2]; })()");
  if (!at.is_array()) throw CdpError("no element " + css_selector + " to click");
  click(at[0].get<double>(), at[1].get<double>());
}

std::string CdpPage::page_errors() const {
  std::string out;
  for (const auto& e : events_) {
    const std::string method = e.value("method", "");
    const auto& p = e.contains("params") ? e["params"] : nlohmann::json::object();
    if (method == "Runtime.exceptionThrown") {
      const auto& d = p.value("exceptionDetails", nlohmann::json::object());
      out += "exception: " + (d.contains("exception") ? d["exception"].value("description", d.value("text", "")) : d.value("text", "")) + "\n";
    } else if (method == "Runtime.consoleAPICalled" && p.value("type", "") == "error") {
      out += "console.error:";
      for (const auto& a : p.value("args", nlohmann::json::array()))
        out += " " + (a.contains("value") ? a["value"].dump() : a.value("description", ""));
      out += "\n";
    }
  }
  return out;
}

void CdpPage::insert_text(const std::string& text) { call("Input.insertText", {{"text", text}}); }

std::string CdpPage::screenshot_png() {
  const nlohmann::json r = call("Page.captureScreenshot", {{"format", "png"}});
  return base64_decode(r.at("data").get<std::string>());
}

}  // namespace fleetmap::test
