#pragma once
// The studio's routes, each with its path pattern, method and body limit, in front of httplib (private
// to the studio module). Knowing every route lets the server answer what httplib alone does not:
// - a known path asked with another method gets 405 and the methods it takes (Allow), an unknown
//   path 404 (httplib says 404 to both);
// - a body is read by its route, up to that route's limit, whatever its content type (httplib caps
//   form-encoded bodies, curl's default type, at 8 KiB with a 413), and a request without
//   Content-Length has none (httplib waits for one until its read timeout, then answers 400).
#include <httplib.h>
// httplib brings <resolv.h>, whose `_res` macro breaks Eigen's products (a parameter of that name).
#undef _res

#include <functional>
#include <regex>
#include <string>
#include <vector>

namespace texsynth::studio {

class StudioRouter {
 public:
  // The request a handler gets carries its body and its pattern's matches.
  using Handler = std::function<void(const httplib::Request&, httplib::Response&)>;
  // Whether a path the pattern matches names something: a page file that exists (405 or 404).
  using Exists = std::function<bool(const std::string& path)>;

  void get(const std::string& pattern, Handler handler, Exists exists = nullptr);
  // Routes with a body of at most `maxBody` bytes (413 above).
  void post(const std::string& pattern, std::size_t maxBody, Handler handler);
  void put(const std::string& pattern, std::size_t maxBody, Handler handler);
  // A route without a body (a body sent is read and ignored).
  void del(const std::string& pattern, Handler handler);

  // Sends every request `server` gets through this table. Call once, after adding the routes.
  void install(httplib::Server& server);

 private:
  struct Route {
    std::string method;
    std::regex pattern;
    std::size_t maxBody = 0;  // 0: the route takes no body
    Handler handler;
    Exists exists;
  };
  void dispatch(const httplib::Request& request, httplib::Response& response, const httplib::ContentReader* body) const;
  std::vector<Route> routes_;
};

}  // namespace texsynth::studio
