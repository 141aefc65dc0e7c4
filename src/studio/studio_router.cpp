// Routing by path and method, bodies read per route.
#include "studio_router.h"

#include <algorithm>
#include <cstdint>
#include <nlohmann/json.hpp>
#include <optional>

namespace texsynth::studio {

namespace {

// HTTP/1.1 (RFC 9112 §6.3): a request has a body only if it says so, by length or by chunks.
bool hasBody(const httplib::Request& request) {
  return request.get_header_value<std::uint64_t>("Content-Length") > 0 ||
         request.get_header_value("Transfer-Encoding").find("chunked") != std::string::npos;
}

// Reads the body and drops it, so the connection is ready for its next request.
void drain(const httplib::Request& request, const httplib::ContentReader& reader) {
  if (!hasBody(request)) return;
  const auto drop = [](const char*, std::size_t) { return true; };
  if (request.is_multipart_form_data())
    reader([](const httplib::MultipartFormData&) { return true; }, drop);
  else
    reader(drop);
}

// "GET, HEAD, POST": the methods of `routes`, in a fixed order, HEAD with GET (httplib answers it so).
std::string allowHeader(const std::vector<std::string>& routes) {
  std::string allow;
  for (const std::string method : {"GET", "HEAD", "POST", "PUT", "PATCH", "DELETE"}) {
    const std::string route = method == "HEAD" ? "GET" : method;
    if (std::find(routes.begin(), routes.end(), route) != routes.end()) allow += (allow.empty() ? "" : ", ") + method;
  }
  return allow;
}

void sendError(httplib::Response& response, int status, const std::string& message) {
  response.status = status;
  response.set_content(nlohmann::json{{"error", message}}.dump(), "application/json");
}

// The body, whole; nothing (with the answer set) when it is over `limit` or cannot be read. Read to
// its end either way, so the connection is ready for its next request.
std::optional<std::string> readBody(const httplib::Request& request, httplib::Response& response,
                                    const httplib::ContentReader& reader, std::size_t limit) {
  if (!hasBody(request)) return std::string();
  if (request.is_multipart_form_data()) {
    drain(request, reader);
    sendError(response, 415, "send the file itself as the body (curl --data-binary @FILE), not a form (-F)");
    return std::nullopt;
  }
  std::string body;
  bool over = false;
  const bool read = reader([&](const char* data, std::size_t length) {
    over = over || body.size() + length > limit;
    if (over)
      std::string().swap(body);  // keep reading, store nothing
    else
      body.append(data, length);
    return true;
  });
  // httplib refuses a declared length over its own cap (413) before reading.
  if (over || response.status == 413) {
    sendError(response, 413, "the body is over this route's limit of " + std::to_string(limit) + " bytes");
    return std::nullopt;
  }
  if (!read) {
    sendError(response, 400, "the request's body could not be read");
    return std::nullopt;
  }
  return body;
}

}  // namespace

void StudioRouter::get(const std::string& pattern, Handler handler, Exists exists) {
  routes_.push_back({"GET", std::regex(pattern), 0, std::move(handler), std::move(exists)});
}

void StudioRouter::post(const std::string& pattern, std::size_t maxBody, Handler handler) {
  routes_.push_back({"POST", std::regex(pattern), maxBody, std::move(handler), nullptr});
}

void StudioRouter::put(const std::string& pattern, std::size_t maxBody, Handler handler) {
  routes_.push_back({"PUT", std::regex(pattern), maxBody, std::move(handler), nullptr});
}

void StudioRouter::del(const std::string& pattern, Handler handler) {
  routes_.push_back({"DELETE", std::regex(pattern), 0, std::move(handler), nullptr});
}

void StudioRouter::dispatch(const httplib::Request& request, httplib::Response& response,
                            const httplib::ContentReader* body) const {
  const std::string method = request.method == "HEAD" ? "GET" : request.method;
  const Route* route = nullptr;
  std::vector<std::string> allowed;
  for (const Route& r : routes_) {
    if (!std::regex_match(request.path, r.pattern)) continue;
    if (r.method == method) {
      route = &r;
      break;
    }
    if (!r.exists || r.exists(request.path)) allowed.push_back(r.method);
  }
  if (!route) {
    if (body) drain(request, *body);
    if (allowed.empty()) return sendError(response, 404, "no such route: " + request.method + " " + request.path);
    const std::string allow = allowHeader(allowed);
    response.set_header("Allow", allow);
    if (request.method == "OPTIONS") {  // the question OPTIONS asks
      response.status = 204;
      return;
    }
    return sendError(response, 405, request.method + " " + request.path + ": this route takes " + allow);
  }
  // The handler's request: this one with its body and the route's matches (which point into its path).
  httplib::Request routed = request;
  if (body && route->maxBody == 0) {
    drain(request, *body);  // a route that takes no body ignores one
  } else if (body) {
    std::optional<std::string> bytes = readBody(request, response, *body, route->maxBody);
    if (!bytes) return;
    routed.body = std::move(*bytes);
  }
  std::regex_match(routed.path, routed.matches, route->pattern);
  route->handler(routed, response);
}

void StudioRouter::install(httplib::Server& server) {
  const std::string any = ".*";
  const auto plain = [this](const httplib::Request& request, httplib::Response& response) {
    dispatch(request, response, nullptr);
  };
  // Methods that may carry a body read it through the route (httplib's content reader).
  const auto withBody = [this](const httplib::Request& request, httplib::Response& response,
                               const httplib::ContentReader& reader) { dispatch(request, response, &reader); };
  server.Get(any, plain);
  server.Options(any, plain);
  server.Post(any, httplib::Server::HandlerWithContentReader(withBody));
  server.Put(any, httplib::Server::HandlerWithContentReader(withBody));
  server.Patch(any, httplib::Server::HandlerWithContentReader(withBody));
  server.Delete(any, httplib::Server::HandlerWithContentReader(withBody));
}

}  // namespace texsynth::studio
