#include "server/web/http/reader_pool.h"

#include "protocol/connection.h"

namespace fleetmap::web {

ReaderPool::Lease::~Lease() {
  if (c_) pool_->give_back(std::move(c_));
}

ReaderPool::Lease ReaderPool::acquire() {
  std::unique_ptr<mysqlpp::Connection> c;
  {
    std::unique_lock lock(mutex_);
    freed_.wait(lock, [&] { return !idle_.empty() || leased_ + idle_.size() < size_; });
    if (!idle_.empty()) {
      c = std::move(idle_.back());
      idle_.pop_back();
    }
    ++leased_;
  }
  try {
    if (c && !c->ping()) c.reset();  // dropped by the server (wait_timeout, restart)
    if (!c) c = connect(web_);
  } catch (...) {
    std::lock_guard lock(mutex_);
    --leased_;
    freed_.notify_one();
    throw;
  }
  return Lease(*this, std::move(c));
}

void ReaderPool::give_back(std::unique_ptr<mysqlpp::Connection> c) {
  std::lock_guard lock(mutex_);
  --leased_;
  idle_.push_back(std::move(c));
  freed_.notify_one();
}

}  // namespace fleetmap::web
