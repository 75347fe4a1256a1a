#pragma once
// What every connection shares: the request pipeline, the push hub, the worker threads
// that run blocking handler work, and the settings.
#include <boost/asio/thread_pool.hpp>

#include "server/web/http/dispatcher.h"
#include "server/web/http/push_hub.h"
#include "server/web/http/web_config.h"

namespace fleetmap::web {

struct WebRuntime {
  Dispatcher& dispatcher;
  PushHub& hub;
  boost::asio::thread_pool& workers;
  const WebConfig& config;
};

}  // namespace fleetmap::web
