#pragma once
// One WebSocket client of /api/ws (docs/web-api.md "The feed"): a PushClient whose
// frames go out one at a time on the connection's strand. What the hub pushes while a
// frame is in flight waits in the client's PushQueue, coalesced, so a client that does
// not read costs one state per robot and never delays the hub or the other clients.
#include <memory>
#include <mutex>
#include <string>

#include <boost/asio/post.hpp>
#include <boost/beast/core.hpp>
#include <boost/beast/websocket.hpp>
#include <spdlog/spdlog.h>

#include "server/web/http/push_queue.h"
#include "server/web/http/web_runtime.h"

namespace fleetmap::web {

inline constexpr int kSendBuffer = 32 * 1024;

template <class Stream>
class WsClient : public PushClient, public std::enable_shared_from_this<WsClient<Stream>> {
 public:
  WsClient(Stream&& stream, WebRuntime& rt, Principal who, std::string peer)
      : ws_(std::move(stream)), rt_(rt), who_(std::move(who)), peer_(std::move(peer)) {}

  void start(HttpRequest req) {
    namespace websocket = boost::beast::websocket;
    // The WebSocket keeps its own timeouts: pings at half the idle time, closed when the
    // peer answers nothing for the whole of it.
    boost::beast::get_lowest_layer(ws_).expires_never();
    // A small kernel send buffer (Linux doubles it): a slow client's backlog in the
    // kernel stays at a few frames, so it gets coalesced, fresh states sooner, and a
    // stalled one costs 64 KiB of kernel memory rather than the autotuned megabytes.
    boost::system::error_code ignored;
    boost::beast::get_lowest_layer(ws_).socket().set_option(boost::asio::socket_base::send_buffer_size(kSendBuffer),
                                                             ignored);
    ws_.set_option(websocket::stream_base::timeout::suggested(boost::beast::role_type::server));
    ws_.set_option(websocket::stream_base::decorator(
        [](websocket::response_type& res) { res.set(boost::beast::http::field::server, "fleetmap-web"); }));
    ws_.read_message_max(64 * 1024);  // clients send nothing the server reads
    ws_.async_accept(req, [self = this->shared_from_this()](boost::beast::error_code ec) { self->on_accept(ec); });
  }

  void push(const FeedUpdate& update, bool first) override {
    {
      std::lock_guard lock(mutex_);
      queue_.robots(update.robots, first);
      queue_.tasks(update.tasks);
    }
    boost::asio::post(ws_.get_executor(), [w = this->weak_from_this()] {
      if (auto self = w.lock()) self->kick();
    });
  }

 private:
  void on_accept(boost::beast::error_code ec) {
    if (ec) return spdlog::debug("ws {}: handshake failed: {}", peer_, ec.message());
    spdlog::info("ws {}: {} subscribed to the feed", peer_, who_.user);
    {
      std::lock_guard lock(mutex_);
      queue_.hello({{"type", "hello"}, {"user", who_.user}, {"role", to_string(who_.role)}});
    }
    rt_.hub.subscribe(this->shared_from_this());
    read();
  }

  // Sends the next frame unless one is in flight. Runs on the strand.
  void kick() {
    if (closed_) return;
    std::optional<std::string> f;
    {
      std::lock_guard lock(mutex_);
      f = queue_.take();
    }
    if (!f) return;
    frame_ = std::move(*f);
    ws_.text(true);
    ws_.async_write(boost::asio::buffer(frame_),
                    [self = this->shared_from_this()](boost::beast::error_code ec, size_t) { self->on_write(ec); });
  }

  void on_write(boost::beast::error_code ec) {
    {
      std::lock_guard lock(mutex_);
      queue_.sent();
    }
    if (ec) {
      closed_ = true;
      return;
    }
    kick();
  }

  // Reads (and drops) what the client sends: that is how a close or a pong arrives.
  void read() {
    ws_.async_read(in_, [self = this->shared_from_this()](boost::beast::error_code ec, size_t) {
      if (ec) {
        self->closed_ = true;
        spdlog::debug("ws {}: closed: {}", self->peer_, ec.message());
        return;
      }
      self->in_.consume(self->in_.size());
      self->read();
    });
  }

  boost::beast::websocket::stream<Stream> ws_;
  WebRuntime& rt_;
  Principal who_;
  std::string peer_;
  std::mutex mutex_;  // queue_: pushed from the feed thread, taken on the strand
  PushQueue queue_;
  std::string frame_;  // the frame in flight
  boost::beast::flat_buffer in_;
  bool closed_ = false;  // strand only
};

}  // namespace fleetmap::web
