#include "tests/integration/web_client.h"

#include <algorithm>
#include <functional>
#include <stdexcept>

#include <boost/asio/connect.hpp>
#include <boost/asio/io_context.hpp>
#include <boost/asio/ip/tcp.hpp>
#include <boost/asio/ssl.hpp>
#include <boost/beast/core.hpp>
#include <boost/beast/http.hpp>
#include <boost/beast/ssl.hpp>
#include <boost/beast/websocket.hpp>
#include <boost/beast/websocket/ssl.hpp>

namespace fleetmap::test {
namespace beast = boost::beast;
namespace http = beast::http;
namespace websocket = beast::websocket;
namespace net = boost::asio;
namespace ssl = net::ssl;
using tcp = net::ip::tcp;

namespace {

std::string lower(std::string s) {
  std::transform(s.begin(), s.end(), s.begin(), [](unsigned char c) { return std::tolower(c); });
  return s;
}

std::string str(beast::string_view s) { return std::string(s.data(), s.size()); }

// A test's certificate is self-signed: the client checks nothing.
ssl::context& client_tls() {
  static ssl::context ctx = [] {
    ssl::context c(ssl::context::tls_client);
    c.set_verify_mode(ssl::verify_none);
    return c;
  }();
  return ctx;
}

template <class Stream>
WebResponse exchange(Stream& stream, http::request<http::string_body>& req) {
  http::write(stream, req);
  beast::flat_buffer buffer;
  http::response_parser<http::string_body> parser;
  parser.body_limit(64u << 20);
  http::read(stream, buffer, parser);
  const auto& res = parser.get();
  WebResponse out;
  out.status = res.result_int();
  out.body = res.body();
  for (const auto& f : res) {
    std::string& h = out.headers[lower(str(f.name_string()))];
    h += (h.empty() ? "" : ", ") + str(f.value());
  }
  return out;
}

}  // namespace

std::string WebResponse::header(const std::string& lowercase_name) const {
  auto it = headers.find(lowercase_name);
  return it == headers.end() ? "" : it->second;
}

WebClient::WebClient(std::string host, unsigned short port, bool tls) : host_(std::move(host)), port_(port), tls_(tls) {}

WebResponse WebClient::request(const std::string& method, const std::string& target, const std::string& body,
                               const std::map<std::string, std::string>& headers, bool with_csrf) {
  net::io_context ioc;
  tcp::resolver resolver(ioc);
  const auto endpoints = resolver.resolve(host_, std::to_string(port_));
  http::request<http::string_body> req{http::string_to_verb(method), target, 11};
  req.set(http::field::host, host_ + ":" + std::to_string(port_));
  if (!cookie.empty()) req.set(http::field::cookie, "fleetmap_session=" + cookie);
  if (with_csrf && !csrf.empty()) req.set("X-CSRF-Token", csrf);
  for (const auto& [k, v] : headers) req.set(k, v);
  req.body() = body;
  req.prepare_payload();
  WebResponse res;
  if (tls_) {
    beast::ssl_stream<beast::tcp_stream> stream(ioc, client_tls());
    beast::get_lowest_layer(stream).expires_after(std::chrono::seconds(30));
    beast::get_lowest_layer(stream).connect(endpoints);
    stream.handshake(ssl::stream_base::client);
    res = exchange(stream, req);
  } else {
    beast::tcp_stream stream(ioc);
    stream.expires_after(std::chrono::seconds(30));
    stream.connect(endpoints);
    res = exchange(stream, req);
  }
  const std::string set_cookie = res.header("set-cookie");
  const std::string prefix = "fleetmap_session=";
  if (set_cookie.rfind(prefix, 0) == 0) cookie = set_cookie.substr(prefix.size(), set_cookie.find(';') - prefix.size());
  return res;
}

WebResponse WebClient::login(const std::string& user, const std::string& password) {
  WebResponse r = post("/api/login", {{"user", user}, {"password", password}});
  if (r.status == 200) csrf = r.json().value("csrf", "");
  return r;
}

std::string WebClient::raw(const std::string& bytes, std::chrono::milliseconds timeout) {
  net::io_context ioc;
  tcp::resolver resolver(ioc);
  beast::tcp_stream stream(ioc);
  stream.connect(resolver.resolve(host_, std::to_string(port_)));
  stream.expires_after(timeout);  // one deadline for the whole exchange
  std::string out;
  char buf[4096];
  std::function<void()> read_more = [&] {
    stream.async_read_some(net::buffer(buf), [&](beast::error_code ec, size_t n) {
      if (ec) return;
      out.append(buf, n);
      read_more();
    });
  };
  net::async_write(stream, net::buffer(bytes), [&](beast::error_code, size_t) { read_more(); });
  ioc.run();
  return out;
}

struct FeedClient::Impl {
  virtual ~Impl() = default;
  virtual std::optional<nlohmann::json> next(std::chrono::milliseconds timeout) = 0;
  virtual unsigned short local_port() const = 0;
};

namespace {

template <class Next>
struct WsImpl : FeedClient::Impl {
  using Ws = websocket::stream<Next>;
  net::io_context ioc;
  std::unique_ptr<Ws> ws;
  beast::flat_buffer buffer;

  WsImpl(const WebClient& web, const std::string& cookie, const std::string& origin, int receive_buffer) {
    tcp::resolver resolver(ioc);
    const auto endpoints = resolver.resolve(web.host(), std::to_string(web.port()));
    if constexpr (std::is_same_v<Next, beast::tcp_stream>) ws = std::make_unique<Ws>(ioc);
    else ws = std::make_unique<Ws>(ioc, client_tls());
    auto& tcp_layer = beast::get_lowest_layer(*ws);
    tcp_layer.socket().open(tcp::v4());
    if (receive_buffer > 0) tcp_layer.socket().set_option(net::socket_base::receive_buffer_size(receive_buffer));
    tcp_layer.expires_after(std::chrono::seconds(10));
    // One endpoint, on the socket opened above: connecting to a range reopens the
    // socket and would lose its receive buffer size.
    tcp_layer.socket().connect(*endpoints.begin());
    if constexpr (!std::is_same_v<Next, beast::tcp_stream>) ws->next_layer().handshake(ssl::stream_base::client);
    ws->set_option(websocket::stream_base::decorator([cookie, origin](websocket::request_type& req) {
      if (!cookie.empty()) req.set(http::field::cookie, "fleetmap_session=" + cookie);
      if (!origin.empty()) req.set(http::field::origin, origin);
    }));
    websocket::response_type res;
    beast::error_code ec;
    ws->handshake(res, web.host() + ":" + std::to_string(web.port()), "/api/ws", ec);
    if (ec) {
      // Beast 1.74 leaves res empty when the upgrade is declined: ask again as plain
      // HTTP with the same headers to learn the status the server refused it with.
      WebClient again = web;
      again.cookie = cookie;
      std::map<std::string, std::string> h = {{"Upgrade", "websocket"}, {"Connection", "Upgrade"},
                                              {"Sec-WebSocket-Key", "dGhlIHNhbXBsZSBub25jZQ=="},
                                              {"Sec-WebSocket-Version", "13"}};
      if (!origin.empty()) h["Origin"] = origin;
      const WebResponse refused = again.request("GET", "/api/ws", "", h, false);
      throw WsRefused(refused.status, "WebSocket refused: " + ec.message() + " (HTTP " +
                                          std::to_string(refused.status) + " " + refused.body + ")");
    }
    tcp_layer.expires_never();
  }

  unsigned short local_port() const override {
    return beast::get_lowest_layer(*ws).socket().local_endpoint().port();
  }

  // A read outlives a timeout: the next call waits on the same one, so a short poll
  // never cancels (and breaks) the WebSocket.
  std::optional<nlohmann::json> next(std::chrono::milliseconds timeout) override {
    if (!pending) {
      buffer.consume(buffer.size());
      done = false;
      ws->async_read(buffer, [this](beast::error_code ec, size_t) {
        result = ec;
        done = true;
      });
      pending = true;
    }
    const auto deadline = std::chrono::steady_clock::now() + timeout;
    while (!done && std::chrono::steady_clock::now() < deadline) {
      if (ioc.stopped()) ioc.restart();
      ioc.run_one_for(deadline - std::chrono::steady_clock::now());
    }
    if (!done) return std::nullopt;
    pending = false;
    if (result) return std::nullopt;
    return nlohmann::json::parse(beast::buffers_to_string(buffer.data()));
  }

  bool pending = false, done = false;
  beast::error_code result;
};

}  // namespace

FeedClient::FeedClient(const WebClient& web, const std::string& cookie, const std::string& origin, int receive_buffer) {
  if (web.tls())
    impl_ = std::make_unique<WsImpl<beast::ssl_stream<beast::tcp_stream>>>(web, cookie, origin, receive_buffer);
  else
    impl_ = std::make_unique<WsImpl<beast::tcp_stream>>(web, cookie, origin, receive_buffer);
}

FeedClient::~FeedClient() = default;

unsigned short FeedClient::local_port() const { return impl_->local_port(); }

std::optional<nlohmann::json> FeedClient::next(std::chrono::milliseconds timeout) { return impl_->next(timeout); }

}  // namespace fleetmap::test
