#pragma once
// fleetmap-web's server (docs/web-api.md): the listener, IO threads, worker threads, the
// TLS context and the feed, started and stopped as one. web_main.cpp only parses
// options and runs this.
#include <atomic>
#include <memory>
#include <thread>
#include <vector>

#include <boost/asio/io_context.hpp>
#include <boost/asio/steady_timer.hpp>
#include <boost/asio/ip/tcp.hpp>
#include <boost/asio/ssl/context.hpp>
#include <boost/asio/thread_pool.hpp>

#include "protocol/db_settings.h"
#include "server/core/server_config.h"
#include "server/web/api/api.h"
#include "server/web/http/dispatcher.h"
#include "server/web/http/fleet_feed.h"
#include "server/web/http/push_hub.h"
#include "server/web/http/web_config.h"
#include "server/web/http/web_runtime.h"

namespace fleetmap::web {

// An SSL context from a PEM certificate chain and key; throws std::invalid_argument
// naming the file OpenSSL refused.
std::unique_ptr<boost::asio::ssl::context> tls_context(const std::string& cert, const std::string& key);

class WebServer {
 public:
  WebServer(WebConfig config, DbSettings web, std::vector<Route> routes, ServerConfig planning);
  ~WebServer();

  // Binds listen:http_port (throws std::runtime_error naming the address when it cannot),
  // starts the threads and the feed; returns the port bound (http_port 0: the kernel's).
  unsigned short start();
  void stop();  // closes the listener, ends the feed and the threads; idempotent

  PushHub& hub() { return hub_; }
  Dispatcher& dispatcher() { return dispatcher_; }

 private:
  void accept();
  void sweep_sessions();  // every minute: idle sessions end, their connections close

  WebConfig config_;
  Dispatcher dispatcher_;
  PushHub hub_;
  FleetFeed feed_;
  boost::asio::io_context ioc_;
  boost::asio::thread_pool workers_;
  std::unique_ptr<boost::asio::ssl::context> tls_;
  boost::asio::ip::tcp::acceptor acceptor_;
  boost::asio::steady_timer sweep_;
  WebRuntime runtime_;
  std::vector<std::thread> io_threads_;
  std::atomic<bool> stopped_{false};
  bool started_ = false;
};

}  // namespace fleetmap::web
