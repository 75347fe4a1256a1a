#pragma once
// One client connection (plain TCP or TLS): reads requests with Beast's parser (header
// 8 KiB, body max_body_bytes: 413 beyond, 30 s to send a request), runs each on the
// worker pool so the IO threads never wait on the database, writes the response back on
// the connection's strand, keeps the connection alive as HTTP/1.1 says, and hands a
// WebSocket upgrade of /api/ws to a WsClient.
#include <chrono>
#include <memory>
#include <optional>
#include <string>
#include <type_traits>

#include <boost/asio/post.hpp>
#include <boost/asio/ssl.hpp>
#include <boost/beast/core.hpp>
#include <boost/beast/http.hpp>
#include <boost/beast/ssl.hpp>
#include <boost/beast/websocket.hpp>
#include <spdlog/spdlog.h>

#include "server/web/http/web_runtime.h"
#include "server/web/http/ws_client.h"

namespace fleetmap::web {

inline constexpr size_t kHeaderLimit = 8 * 1024;
inline constexpr std::chrono::seconds kReadTimeout{30};

template <class Stream>
class HttpConnection : public std::enable_shared_from_this<HttpConnection<Stream>> {
  static constexpr bool kTls = !std::is_same_v<Stream, boost::beast::tcp_stream>;
  using Self = HttpConnection<Stream>;

 public:
  HttpConnection(Stream&& stream, WebRuntime& rt, std::string peer)
      : stream_(std::move(stream)), rt_(rt), peer_(std::move(peer)) {}

  void start() {
    if constexpr (kTls) {
      boost::beast::get_lowest_layer(stream_).expires_after(kReadTimeout);
      stream_.async_handshake(boost::asio::ssl::stream_base::server,
                              [self = this->shared_from_this()](boost::beast::error_code ec) {
                                if (ec) return spdlog::debug("{}: TLS handshake failed: {}", self->peer_, ec.message());
                                self->read();
                              });
    } else {
      read();
    }
  }

 private:
  void read() {
    parser_.emplace();
    parser_->header_limit(kHeaderLimit);
    parser_->body_limit(rt_.config.max_body_bytes);
    boost::beast::get_lowest_layer(stream_).expires_after(kReadTimeout);
    boost::beast::http::async_read(stream_, buffer_, *parser_,
                                   [self = this->shared_from_this()](boost::beast::error_code ec, size_t) {
                                     self->on_read(ec);
                                   });
  }

  void on_read(boost::beast::error_code ec) {
    namespace http = boost::beast::http;
    if (ec == http::error::end_of_stream || ec == boost::beast::error::timeout || ec == boost::asio::error::eof)
      return close();
    if (ec == http::error::body_limit)
      return refuse(413, "payload_too_large",
                    "the request body is larger than max_body_bytes (" + std::to_string(rt_.config.max_body_bytes) + ")");
    if (ec == http::error::header_limit)
      return refuse(431, "headers_too_large", "the request headers are larger than 8 KiB");
    if (ec) {
      if (ec.category() == http::make_error_code(http::error::bad_target).category())
        return refuse(400, "bad_request", "malformed HTTP request: " + ec.message());
      return close();
    }
    HttpRequest req = parser_->release();
    if (boost::beast::websocket::is_upgrade(req)) return upgrade(std::move(req));
    auto self = this->shared_from_this();
    boost::asio::post(rt_.workers, [self, req = std::move(req)] {
      auto res = std::make_shared<HttpResponse>(self->rt_.dispatcher.handle(req, self->peer_));
      res->keep_alive(req.keep_alive());
      boost::asio::post(self->stream_.get_executor(), [self, res] { self->send(res); });
    });
  }

  void upgrade(HttpRequest req) {
    const std::string target(req.target().data(), req.target().size());
    if (target.substr(0, target.find('?')) != "/api/ws")
      return refuse(404, "not_found", "WebSocket upgrades are only for /api/ws");
    if (!rt_.dispatcher.same_origin(req)) return refuse(403, "forbidden", "the Origin of this WebSocket is not this site");
    auto session = rt_.dispatcher.session_of(req);
    if (!session) return refuse(401, "unauthorized", "sign in first (POST /api/login): the feed needs the session cookie");
    std::make_shared<WsClient<Stream>>(std::move(stream_), rt_, session->who, peer_)->start(std::move(req));
  }

  // An error the connection itself answers; the request was not (wholly) read, so the
  // connection ends after it.
  void refuse(int status, const std::string& code, const std::string& message) {
    HttpRequest head;
    if (parser_) head.version(parser_->get().version());
    auto res = std::make_shared<HttpResponse>(rt_.dispatcher.error(head, status, code, message));
    res->set(boost::beast::http::field::cache_control, "no-store");
    res->set("X-Content-Type-Options", "nosniff");
    res->keep_alive(false);
    send(res);
  }

  void send(std::shared_ptr<HttpResponse> res) {
    res_ = std::move(res);
    boost::beast::get_lowest_layer(stream_).expires_after(kReadTimeout);
    boost::beast::http::async_write(stream_, *res_, [self = this->shared_from_this()](boost::beast::error_code ec, size_t) {
      self->on_write(ec);
    });
  }

  void on_write(boost::beast::error_code ec) {
    if (ec) return close();
    const bool again = res_->keep_alive();
    res_.reset();
    if (again) return read();
    close();
  }

  // Ends the connection after the last response: half-close, then drain what the
  // client still sends for a moment, so that a refused upload's unread bytes do not make
  // the kernel reset the connection before the client read the answer.
  void close() {
    if constexpr (kTls) {
      boost::beast::get_lowest_layer(stream_).expires_after(std::chrono::seconds(2));
      stream_.async_shutdown([self = this->shared_from_this()](boost::beast::error_code) {
        boost::beast::get_lowest_layer(self->stream_).close();
      });
    } else {
      boost::beast::error_code ignored;
      stream_.socket().shutdown(boost::asio::ip::tcp::socket::shutdown_send, ignored);
      stream_.expires_after(std::chrono::seconds(2));
      drain();
    }
  }

  void drain() {
    drain_.resize(16 * 1024);
    stream_.async_read_some(boost::asio::buffer(drain_), [self = this->shared_from_this()](boost::beast::error_code ec, size_t) {
      if (ec) return boost::beast::get_lowest_layer(self->stream_).close();
      self->drain();
    });
  }

  Stream stream_;
  WebRuntime& rt_;
  std::string peer_;
  boost::beast::flat_buffer buffer_;
  std::optional<boost::beast::http::request_parser<boost::beast::http::string_body>> parser_;
  std::shared_ptr<HttpResponse> res_;
  std::string drain_;
};

}  // namespace fleetmap::web
