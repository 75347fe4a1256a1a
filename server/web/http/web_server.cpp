#include "server/web/http/web_server.h"

#include <stdexcept>

#include <boost/asio/strand.hpp>
#include <spdlog/spdlog.h>

#include "server/web/http/http_connection.h"

namespace fleetmap::web {
namespace net = boost::asio;
namespace ssl = boost::asio::ssl;
using tcp = boost::asio::ip::tcp;

std::unique_ptr<ssl::context> tls_context(const std::string& cert, const std::string& key) {
  auto ctx = std::make_unique<ssl::context>(ssl::context::tls_server);
  // TLS 1.2 and later only.
  ctx->set_options(ssl::context::default_workarounds | ssl::context::no_sslv2 | ssl::context::no_sslv3 |
                   ssl::context::no_tlsv1 | ssl::context::no_tlsv1_1 | ssl::context::single_dh_use);
  try {
    ctx->use_certificate_chain_file(cert);
  } catch (const std::exception& e) {
    throw std::invalid_argument("[web] tls_cert: cannot use " + cert + ": " + e.what());
  }
  try {
    ctx->use_private_key_file(key, ssl::context::pem);
  } catch (const std::exception& e) {
    throw std::invalid_argument("[web] tls_key: cannot use " + key + ": " + e.what());
  }
  return ctx;
}

WebServer::WebServer(WebConfig config, DbSettings web, std::vector<Route> routes, ServerConfig planning)
    : config_(std::move(config)),
      dispatcher_(config_, web, std::move(routes), std::move(planning)),
      feed_(web, config_.feed_period_ms, hub_),
      ioc_(config_.threads),
      workers_(static_cast<size_t>(config_.workers)),
      tls_(config_.tls() ? tls_context(config_.tls_cert, config_.tls_key) : nullptr),
      acceptor_(ioc_),
      sweep_(ioc_),
      runtime_{dispatcher_, hub_, workers_, config_} {}

WebServer::~WebServer() { stop(); }

unsigned short WebServer::start() {
  boost::system::error_code ec;
  const auto address = net::ip::make_address(config_.listen, ec);
  if (ec) throw std::invalid_argument("[web] listen: expected an IP address, got '" + config_.listen + "'");
  const tcp::endpoint ep(address, static_cast<unsigned short>(config_.http_port));
  acceptor_.open(ep.protocol());
  acceptor_.set_option(net::socket_base::reuse_address(true));
  acceptor_.bind(ep, ec);
  if (ec)
    throw std::runtime_error("cannot listen on " + config_.listen + ":" + std::to_string(config_.http_port) + ": " +
                             ec.message());
  acceptor_.listen(net::socket_base::max_listen_connections);
  started_ = true;
  accept();
  sweep_sessions();
  for (int i = 0; i < config_.threads; ++i) io_threads_.emplace_back([this] { ioc_.run(); });
  feed_.start();
  return acceptor_.local_endpoint().port();
}

void WebServer::accept() {
  acceptor_.async_accept(net::make_strand(ioc_), [this](boost::system::error_code ec, tcp::socket socket) {
    if (ec == net::error::operation_aborted || stopped_) return;
    if (!ec) {
      boost::system::error_code pe;
      const auto remote = socket.remote_endpoint(pe);
      const std::string peer = pe ? "?" : remote.address().to_string();
      if (tls_) {
        std::make_shared<HttpConnection<boost::beast::ssl_stream<boost::beast::tcp_stream>>>(
            boost::beast::ssl_stream<boost::beast::tcp_stream>(std::move(socket), *tls_), runtime_, peer)
            ->start();
      } else {
        std::make_shared<HttpConnection<boost::beast::tcp_stream>>(boost::beast::tcp_stream(std::move(socket)), runtime_,
                                                                   peer)
            ->start();
      }
    } else {
      spdlog::warn("accept: {}", ec.message());
    }
    accept();
  });
}

void WebServer::sweep_sessions() {
  sweep_.expires_after(std::chrono::seconds(60));
  sweep_.async_wait([this](boost::system::error_code ec) {
    if (ec || stopped_) return;
    // Closing a connection may wait on the network: not on an IO thread.
    net::post(workers_, [this] {
      if (const size_t n = dispatcher_.sessions().expire()) spdlog::info("{} idle session(s) ended", n);
    });
    sweep_sessions();
  });
}

void WebServer::stop() {
  if (stopped_.exchange(true) || !started_) return;
  feed_.stop();
  net::post(ioc_, [this] {
    boost::system::error_code ignored;
    acceptor_.close(ignored);
    sweep_.cancel();
  });
  ioc_.stop();
  for (auto& t : io_threads_) t.join();
  workers_.join();
}

}  // namespace fleetmap::web
