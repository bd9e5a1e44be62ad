#include "view/server.hpp"

#include <fstream>
#include <iterator>
#include <map>
#include <mutex>
#include <stdexcept>
#include <thread>
#include <chrono>

#include <httplib.h>
#include <nlohmann/json.hpp>

namespace knitc::view {

namespace {

// Every file the server may send besides the fabric: its address -> where it is read from.
// Nothing else of the file system is reachable (a path is looked up, never joined).
const std::map<std::string, std::pair<std::string, const char*>>& assets() {
  static const std::map<std::string, std::pair<std::string, const char*>> files = {
      {"/", {KNITC_VIEW_PAGE_DIR "/index.html", "text/html; charset=utf-8"}},
      {"/view.js", {KNITC_VIEW_PAGE_DIR "/view.js", "text/javascript"}},
      {"/three/three.module.js", {KNITC_THREE_DIR "/build/three.module.js", "text/javascript"}},
      {"/three/three.core.js", {KNITC_THREE_DIR "/build/three.core.js", "text/javascript"}},
      {"/three/addons/loaders/GLTFLoader.js", {KNITC_THREE_DIR "/examples/jsm/loaders/GLTFLoader.js", "text/javascript"}},
      {"/three/addons/utils/BufferGeometryUtils.js", {KNITC_THREE_DIR "/examples/jsm/utils/BufferGeometryUtils.js", "text/javascript"}},
      {"/three/addons/utils/SkeletonUtils.js", {KNITC_THREE_DIR "/examples/jsm/utils/SkeletonUtils.js", "text/javascript"}},
      {"/three/addons/controls/OrbitControls.js", {KNITC_THREE_DIR "/examples/jsm/controls/OrbitControls.js", "text/javascript"}},
      {"/three/addons/libs/meshopt_decoder.module.js",
       {KNITC_THREE_DIR "/examples/jsm/libs/meshopt_decoder.module.js", "text/javascript"}},
  };
  return files;
}

bool read_file(const std::string& path, std::string& out) {
  std::ifstream in(path, std::ios::binary);
  if (!in) return false;
  out.assign(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
  return !in.bad();
}

}  // namespace

bool own_host(const std::string& host, int port) {
  const std::string p = ":" + std::to_string(port);
  return host == "127.0.0.1" + p || host == "localhost" + p;
}

struct Server::State {
  httplib::Server http;
  int port = -1;
  std::mutex mutex;
  std::uint64_t version = 0;         // every publish
  std::uint64_t fabric_version = 0;  // the last publish with a fabric
  Published shown;
};

Server::Server(int port) : state_(std::make_unique<State>()) {
  State& s = *state_;
  // Every request: its Host must be this server's (no other site's page gets here by DNS
  // rebinding), and its path one of the server's own (checked before any route).
  s.http.set_pre_routing_handler([&s](const httplib::Request& req, httplib::Response& res) {
    if (!own_host(req.get_header_value("Host"), s.port)) {
      res.status = 403;
      res.set_content("knitc view answers only to http://127.0.0.1:" + std::to_string(s.port) + "/\n", "text/plain");
      return httplib::Server::HandlerResponse::Handled;
    }
    if (req.path.find("..") != std::string::npos || req.path.find('\\') != std::string::npos || req.path.empty() ||
        req.path[0] != '/') {
      res.status = 400;
      res.set_content("knitc view serves only its own files\n", "text/plain");
      return httplib::Server::HandlerResponse::Handled;
    }
    return httplib::Server::HandlerResponse::Unhandled;
  });
  for (const auto& [address, file] : assets()) {
    const std::string path = file.first;
    const char* type = file.second;
    s.http.Get(address, [path, type](const httplib::Request&, httplib::Response& res) {
      std::string body;
      if (!read_file(path, body)) {
        res.status = 404;
        res.set_content("missing " + path + "; run ./scripts/install-deps\n", "text/plain");
        return;
      }
      res.set_header("Cache-Control", "no-store");
      res.set_content(std::move(body), type);
    });
  }
  s.http.Get("/favicon.ico", [](const httplib::Request&, httplib::Response& res) { res.status = 204; });
  s.http.Get("/state", [&s](const httplib::Request&, httplib::Response& res) {
    std::lock_guard lock(s.mutex);
    const nlohmann::json state = {{"version", s.version},
                                  {"fabric", s.fabric_version},
                                  {"error", s.shown.error},
                                  {"warnings", s.shown.warnings}};
    res.set_header("Cache-Control", "no-store");
    res.set_content(state.dump(), "application/json");
  });
  s.http.Get("/fabric.glb", [&s](const httplib::Request&, httplib::Response& res) {
    std::lock_guard lock(s.mutex);
    res.set_header("Cache-Control", "no-store");
    res.set_content(s.shown.glb, "model/gltf-binary");
  });
  s.http.Get("/fabric.json", [&s](const httplib::Request&, httplib::Response& res) {
    std::lock_guard lock(s.mutex);
    res.set_header("Cache-Control", "no-store");
    res.set_content(s.shown.info, "application/json");
  });
  s.port = port == 0 ? s.http.bind_to_any_port("127.0.0.1") : (s.http.bind_to_port("127.0.0.1", port) ? port : -1);
  if (s.port <= 0)
    throw std::runtime_error(port == 0 ? std::string("cannot listen on 127.0.0.1")
                                       : "cannot listen on 127.0.0.1:" + std::to_string(port) + " (in use?); try another --port, or 0");
}

Server::~Server() { stop(); }

int Server::port() const { return state_->port; }

std::string Server::address() const { return "http://127.0.0.1:" + std::to_string(state_->port) + "/"; }

void Server::publish(Published p) {
  std::lock_guard lock(state_->mutex);
  ++state_->version;
  if (!p.glb.empty()) {
    state_->fabric_version = state_->version;
    state_->shown = std::move(p);
  } else {
    state_->shown.error = std::move(p.error);
    state_->shown.warnings = std::move(p.warnings);
  }
}

void Server::run() { state_->http.listen_after_bind(); }

bool Server::wait_until_serving() const {
  for (int i = 0; i < 2000 && !state_->http.is_running(); ++i) std::this_thread::sleep_for(std::chrono::milliseconds(1));
  return state_->http.is_running();
}

void Server::stop() {
  if (state_ && state_->http.is_running()) state_->http.stop();
}

}  // namespace knitc::view
