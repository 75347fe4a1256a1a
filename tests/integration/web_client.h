#pragma once
// A small blocking HTTP(S)/WebSocket client of fleetmap-web for the integration tests
// (Boost.Beast): a cookie jar holding the session cookie, the CSRF token from login,
// raw exchanges for what a browser would never send, and a feed reader.
#include <chrono>
#include <map>
#include <memory>
#include <optional>
#include <string>

#include <nlohmann/json.hpp>

namespace fleetmap::test {

struct WebResponse {
  int status = 0;
  std::string body;
  std::map<std::string, std::string> headers;  // names in lowercase
  nlohmann::json json() const { return nlohmann::json::parse(body); }
  std::string header(const std::string& lowercase_name) const;
};

class WebClient {
 public:
  WebClient(std::string host, unsigned short port, bool tls = false);

  // One request on a new connection; sends the jar's session cookie and, when with_csrf,
  // the CSRF token; keeps a Set-Cookie of the session. Throws on a network error.
  WebResponse request(const std::string& method, const std::string& target, const std::string& body = "",
                      const std::map<std::string, std::string>& headers = {}, bool with_csrf = true);
  WebResponse get(const std::string& target) { return request("GET", target); }
  WebResponse post(const std::string& target, const nlohmann::json& body) {
    return request("POST", target, body.dump(), {{"Content-Type", "application/json"}});
  }
  // POST /api/login; on 200 keeps the CSRF token.
  WebResponse login(const std::string& user, const std::string& password);

  // Sends bytes as they are on a new connection and returns everything the server sends
  // back until it closes the connection (or timeout).
  std::string raw(const std::string& bytes, std::chrono::milliseconds timeout = std::chrono::seconds(5));

  std::string cookie;  // the session cookie's value ("" none)
  std::string csrf;
  const std::string& host() const { return host_; }
  unsigned short port() const { return port_; }
  bool tls() const { return tls_; }

 private:
  std::string host_;
  unsigned short port_;
  bool tls_;
};

// A WebSocket on /api/ws. The constructor does the handshake; a refused upgrade throws
// WsRefused with the HTTP status.
struct WsRefused : std::runtime_error {
  WsRefused(int s, const std::string& what) : std::runtime_error(what), status(s) {}
  int status;
};

class FeedClient {
 public:
  // cookie "": none; origin "": no Origin header. receive_buffer > 0: SO_RCVBUF of the
  // socket (a client that reads slowly or never).
  FeedClient(const WebClient& web, const std::string& cookie, const std::string& origin = "", int receive_buffer = 0);
  ~FeedClient();
  unsigned short local_port() const;
  // The next message, or nullopt after timeout.
  std::optional<nlohmann::json> next(std::chrono::milliseconds timeout = std::chrono::seconds(10));

  struct Impl;

 private:
  std::unique_ptr<Impl> impl_;
};

}  // namespace fleetmap::test
