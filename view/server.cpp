#include "view/server.hpp"

#include "view/assets.hpp"

#include <mutex>
#include <stdexcept>
#include <string_view>
#include <string_view>
#include <thread>
#include <chrono>

#include <httplib.h>
#include <nlohmann/json.hpp>

namespace knitc::view {


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
  for (const Asset& asset : assets()) {
    if (std::string_view(asset.address) == "/pattern.html") continue;  // served filled in, at /
    const std::string path = asset.path;
    const char* type = asset.type;
    s.http.Get(asset.address, [path, type](const httplib::Request&, httplib::Response& res) {
      std::string body;
      if (!read_asset(path, body)) {
        res.status = 404;
        res.set_content("missing " + path + "; run ./scripts/install-deps\n", "text/plain");
        return;
      }
      res.set_header("Cache-Control", "no-store");
      res.set_content(std::move(body), type);
    });
  }
  // The page: the template with the live view's parts (modules by an import map, polling).
  s.http.Get("/", [](const httplib::Request&, httplib::Response& res) {
    std::string page;
    if (!read_asset(KNITC_VIEW_PAGE_DIR "/pattern.html", page)) {
      res.status = 404;
      return;
    }
    res.set_header("Cache-Control", "no-store");
    res.set_content(filled(std::move(page),
                           {{"title", "knitc view"},
                            {"head", "<script type=\"importmap\">{\"imports\": {\"three\": \"/three/three.module.js\", "
                                     "\"three/addons/\": \"/three/addons/\"}}</script>\n<link rel=\"stylesheet\" href=\"/view.css\">"},
                            {"home", ""},
                            {"source", ""},
                            {"scripts", "<script type=\"module\" src=\"/view.js\"></script>"}}),
                    "text/html; charset=utf-8");
  });
  s.http.Get("/favicon.ico", [](const httplib::Request&, httplib::Response& res) { res.status = 204; });
  s.http.Get("/state", [&s](const httplib::Request&, httplib::Response& res) {
    std::lock_guard lock(s.mutex);
    const nlohmann::json state = {{"version", s.version},
                                  {"fabric", s.fabric_version},
                                  {"error", s.shown.error},
                                  {"warnings", s.shown.warnings}};
    res.set_header("Cache-Control", "no-store");
    res.set_content(state.dump(), "application/json; charset=utf-8");
  });
  s.http.Get("/fabric.glb", [&s](const httplib::Request&, httplib::Response& res) {
    std::lock_guard lock(s.mutex);
    res.set_header("Cache-Control", "no-store");
    res.set_content(s.shown.glb, "model/gltf-binary");
  });
  s.http.Get("/fabric.json", [&s](const httplib::Request&, httplib::Response& res) {
    std::lock_guard lock(s.mutex);
    res.set_header("Cache-Control", "no-store");
    res.set_content(s.shown.info, "application/json; charset=utf-8");  // not compressed: see assets.hpp
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
