// The live view's server (knitc view): serves a page, three.js and the current fabric
// on 127.0.0.1 only, and nothing else of the file system. Pure plumbing: what it serves
// is published to it as bytes; building the fabric is the caller's.
#pragma once

#include <cstdint>
#include <memory>
#include <string>

namespace knitc::view {

// What the page shows: the fabric of the last build that worked, and the problem of the
// last one if it did not.
struct Published {
  std::string glb;         // the fabric, a glTF binary
  std::string info;        // JSON: the pattern's loops, chart and figures (writers::view_json)
  std::string error;       // empty when the last build worked: else "file:line: message"
  std::string warnings;    // the last build's warnings, a line each
};

class Server {
 public:
  // Listens on 127.0.0.1:`port` (0: a free port). Throws std::runtime_error if it cannot.
  explicit Server(int port);
  ~Server();
  Server(const Server&) = delete;
  Server& operator=(const Server&) = delete;

  int port() const;
  // The page's address, http://127.0.0.1:PORT/
  std::string address() const;
  // Makes `p` what the page is served; the fabric and info are kept from the last call
  // that had them when `p.glb` is empty (a build that failed). Thread-safe.
  void publish(Published p);
  // Serves until stop() (from another thread).
  void run();
  // Waits (up to 2 s) until run() serves, so that a stop() is not lost before it.
  bool wait_until_serving() const;
  void stop();

 private:
  struct State;
  std::unique_ptr<State> state_;
};

// Whether a request's Host header names this server ("127.0.0.1:PORT" or
// "localhost:PORT"): a page of another site that a DNS rebinding points here sends its
// own name and is refused.
bool own_host(const std::string& host, int port);

}  // namespace knitc::view
