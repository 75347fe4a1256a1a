#pragma once
// The web account's read-only connections (ApiContext::reader(), sql/80_web.sql): at most
// one per worker thread, opened when first needed, checked with ping() when taken and
// opened again when the server dropped them.
#include <condition_variable>
#include <memory>
#include <mutex>
#include <vector>

#include <mysql++/mysql++.h>

#include "protocol/db_settings.h"

namespace fleetmap::web {

class ReaderPool {
 public:
  ReaderPool(DbSettings web, size_t size) : web_(std::move(web)), size_(size) {}

  // One connection, this holder's alone until it is destroyed.
  class Lease {
   public:
    Lease(ReaderPool& pool, std::unique_ptr<mysqlpp::Connection> c) : pool_(&pool), c_(std::move(c)) {}
    Lease(Lease&& o) noexcept : pool_(o.pool_), c_(std::move(o.c_)) {}
    Lease& operator=(Lease&&) = delete;
    ~Lease();
    mysqlpp::Connection& operator*() { return *c_; }

   private:
    ReaderPool* pool_;
    std::unique_ptr<mysqlpp::Connection> c_;
  };

  // Waits while every connection is leased; throws DbError when none can be opened.
  Lease acquire();
  const DbSettings& settings() const { return web_; }

 private:
  void give_back(std::unique_ptr<mysqlpp::Connection> c);
  DbSettings web_;
  size_t size_;
  std::mutex mutex_;
  std::condition_variable freed_;
  std::vector<std::unique_ptr<mysqlpp::Connection>> idle_;
  size_t leased_ = 0;
};

}  // namespace fleetmap::web
