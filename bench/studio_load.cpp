// texsynth studio through its HTTP API, as the page and many pages use it: single-user latencies
// (a curve to the updated field and glyphs, an exemplar to its first textured preview, lazy cuts),
// then N concurrent clients adding curves and asking for previews, then bad input. Prints markdown
// tables. Run by bench/studio.sh, which starts the server.
// Usage: studio_load PORT SERVER_PID SKETCH.json [--clients N] [--seconds S] [--phases P]
// The load runs P phases of S seconds; the server's memory after each shows whether it keeps growing.
#include <httplib.h>
#undef _res  // from <resolv.h>, via httplib

#include <algorithm>
#include <atomic>
#include <chrono>
#include <condition_variable>
#include <cstdio>
#include <fstream>
#include <map>
#include <mutex>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

using nlohmann::json;
using Clock = std::chrono::steady_clock;

namespace {

int port = 0;

double msSince(Clock::time_point start) {
  return std::chrono::duration<double, std::milli>(Clock::now() - start).count();
}

std::unique_ptr<httplib::Client> client() {
  auto c = std::make_unique<httplib::Client>("127.0.0.1", port);
  c->set_read_timeout(300, 0);
  c->set_keep_alive(true);  // as browsers do: one connection per client, reused
  c->set_tcp_nodelay(true);
  return c;
}

json parse(const httplib::Result& r) {
  return r && !r->body.empty() && r->get_header_value("Content-Type") == "application/json" ? json::parse(r->body)
                                                                                            : json();
}

// The server's resident memory (VmRSS), MiB.
double residentMiB(int pid) {
  std::ifstream status("/proc/" + std::to_string(pid) + "/status");
  std::string line;
  while (std::getline(status, line))
    if (line.rfind("VmRSS:", 0) == 0) return std::stod(line.substr(6)) / 1024.0;
  return 0;
}

// The event stream, read on its own thread: "result" and "job" events by job id.
class EventReader {
 public:
  EventReader() {
    thread_ = std::thread([this] {
      auto c = client();
      std::string pending;
      c->Get("/api/events", [&](const char* data, std::size_t length) {
        pending.append(data, length);
        for (std::size_t end; (end = pending.find("\n\n")) != std::string::npos; pending.erase(0, end + 2)) {
          const std::string block = pending.substr(0, end);
          const std::size_t at = block.find("data: ");
          if (at == std::string::npos) continue;
          json event = json::parse(block.substr(at + 6));
          std::lock_guard<std::mutex> lock(mutex_);
          events_.push_back(std::move(event));
          changed_.notify_all();
        }
        return !stop_;
      });
    });
  }
  ~EventReader() {
    stop_ = true;
    thread_.detach();  // ends at the next event or when the server stops
  }
  // Waits for the result of `job` (of `stage`, if given).
  json result(const std::string& job, const std::string& stage = "") {
    std::unique_lock<std::mutex> lock(mutex_);
    json found;
    changed_.wait_for(lock, std::chrono::seconds(300), [&] {
      for (const json& e : events_)
        if (e.value("job", "") == job && e.contains("url") && (stage.empty() || e.value("stage", "") == stage))
          return found = e, true;
      return false;
    });
    return found;
  }

 private:
  std::thread thread_;
  std::mutex mutex_;
  std::condition_variable changed_;
  std::vector<json> events_;
  std::atomic<bool> stop_{false};
};

struct Samples {
  std::vector<double> ms;
  void add(double v) { ms.push_back(v); }
  double percentile(double p) {
    if (ms.empty()) return 0;
    std::sort(ms.begin(), ms.end());
    return ms[std::min(ms.size() - 1, std::size_t(p * double(ms.size() - 1) + 0.5))];
  }
};

void latencies(const json& sketch, EventReader& events) {
  auto c = client();
  std::printf("## One user\n\n| request | n | p50 ms | p95 ms | max ms |\n|---|---:|---:|---:|---:|\n");
  Samples curve, undo, preview;
  for (int i = 0; i < 30; ++i) {
    const auto start = Clock::now();
    const json added =
        parse(c->Post("/api/sketch/curves", sketch["curves"][i % sketch["curves"].size()].dump(), "application/json"));
    c->Get("/api/field/glyphs?across=16");
    curve.add(msSince(start));
    const auto undoStart = Clock::now();
    c->Delete(("/api/sketch/curves/" + added["id"].get<std::string>()).c_str());
    c->Get("/api/field/glyphs?across=16");
    undo.add(msSince(undoStart));
  }
  const json catalog = parse(c->Get("/api/catalog"));
  for (int i = 0; i < 10; ++i) {
    const std::string exemplar = catalog["exemplars"][std::size_t(i * 5) % catalog["exemplars"].size()]["id"];
    const auto start = Clock::now();
    c->Post("/api/scene", json{{"exemplar", exemplar}}.dump(), "application/json");
    const json job = parse(c->Post("/api/preview", json{{"method", "tile-deform"}}.dump(), "application/json"));
    const json result = events.result(job["job"]);
    c->Get(result["url"].get<std::string>().c_str());
    preview.add(msSince(start));
  }
  for (auto [name, samples] : {std::pair{"new curve -> field + glyphs (grid of the CLI's default)", &curve},
                               std::pair{"undo a curve -> field + glyphs", &undo},
                               std::pair{"exemplar chosen -> first textured preview (colours fetched)", &preview}})
    std::printf("| %s | %zu | %.0f | %.0f | %.0f |\n", name, samples->ms.size(), samples->percentile(0.5),
                samples->percentile(0.95), samples->percentile(1.0));
  // Cuts through the lazy solid: the first builds it (coarsest level over the box), later ones
  // synthesize only the newly exposed voxels.
  std::printf("\n| lazy cut (pink_marble, tiles 2) | ms |\n|---|---:|\n");
  for (const json& entry : catalog["exemplars"])
    if (entry["name"] == "Stone/pink_marble")
      c->Post("/api/scene", json{{"exemplar", entry["id"]}}.dump(), "application/json");
  for (const auto& [axis, position] :
       std::vector<std::pair<std::string, double>>{{"z", 0.5}, {"z", 0.55}, {"z", 0.6}, {"x", 0.5}}) {
    const auto start = Clock::now();
    const json job = parse(c->Post("/api/cut", json{{"axis", axis}, {"position", position}, {"method", "lazy"}}.dump(),
                                   "application/json"));
    events.result(job["job"]);
    std::printf("| %s = %.2f | %.0f |\n", axis.c_str(), position, msSince(start));
  }
}

void load(const json& sketch, int clients, int seconds, int phases, int serverPid) {
  std::mutex mutex;
  std::map<std::string, Samples> byRoute;
  std::map<std::string, int> statuses;  // HTTP status, or the client's error
  std::atomic<bool> stop{false};
  std::vector<double> rss = {residentMiB(serverPid)};
  for (int phase = 0; phase < phases; ++phase) {
    stop = false;
    std::vector<std::thread> threads;
    for (int t = 0; t < clients; ++t)
      threads.emplace_back([&, t] {
        auto c = client();
        for (int round = 0; !stop; ++round) {
          const auto timed = [&](const std::string& route, auto call) {
            const auto start = Clock::now();
            httplib::Result r = call();
            const double ms = msSince(start);
            std::lock_guard<std::mutex> lock(mutex);
            byRoute[route].add(ms);
            ++statuses[r ? std::to_string(r->status)
                         : "no answer (" + httplib::to_string(r.error()) + ", " + route + ", after " +
                               std::to_string(int(ms / 1000)) + " s)"];
            return r;
          };
          const auto curve = sketch["curves"][std::size_t(t + round) % sketch["curves"].size()].dump();
          const json added = parse(timed("POST /api/sketch/curves",
                                         [&] { return c->Post("/api/sketch/curves", curve, "application/json"); }));
          timed("GET /api/field/glyphs", [&] { return c->Get("/api/field/glyphs?across=16"); });
          timed("POST /api/preview", [&] {
            return c->Post("/api/preview", json{{"method", "tile-deform"}}.dump(), "application/json");
          });
          if (added.contains("id"))
            timed("DELETE /api/sketch/curves/ID",
                  [&] { return c->Delete(("/api/sketch/curves/" + added["id"].get<std::string>()).c_str()); });
        }
      });
    std::this_thread::sleep_for(std::chrono::seconds(seconds));
    stop = true;
    for (std::thread& t : threads) t.join();
    std::this_thread::sleep_for(std::chrono::seconds(3));
    rss.push_back(residentMiB(serverPid));
  }
  std::printf("\n## %d clients, %d phases of %d s\n\n| route | requests | p50 ms | p95 ms |\n|---|---:|---:|---:|\n",
              clients, phases, seconds);
  for (auto& [route, samples] : byRoute)
    std::printf("| %s | %zu | %.0f | %.0f |\n", route.c_str(), samples.ms.size(), samples.percentile(0.5),
                samples.percentile(0.95));
  int errors = 0;
  std::string statusText;
  for (const auto& [status, count] : statuses) {
    statusText.append(" ").append(status).append(": ").append(std::to_string(count));
    if (status[0] == '5' || status[0] == 'n') errors += count;
  }
  std::printf("\nstatuses:%s; 5xx or no answer: %d\n", statusText.c_str(), errors);
  std::string memory;
  for (double mib : rss) memory.append(memory.empty() ? "" : " -> ").append(std::to_string(int(mib + 0.5)));
  std::printf("server memory (MiB) before and 3 s after each phase: %s\n", memory.c_str());
}

void badInput() {
  auto c = client();
  std::printf("\n## Bad input\n\n| request | status | answer |\n|---|---:|---|\n");
  const auto show = [](const char* what, const httplib::Result& r) {
    std::string body = r ? r->body.substr(0, 110) : "(no answer)";
    std::replace(body.begin(), body.end(), '|', '/');
    std::printf("| %s | %d | %s |\n", what, r ? r->status : 0, body.c_str());
  };
  show("mesh upload of 80 MiB", c->Post("/api/uploads/mesh?format=obj", std::string(80u << 20, 'v'), "text/plain"));
  show("truncated OFF mesh", c->Post("/api/uploads/mesh?format=off", "OFF\n8 12 0\n0 0 0\n1 0 0\n", "text/plain"));
  show("PNG that is not one", c->Post("/api/uploads/exemplar?format=png", std::string("\x89PNG\r\n", 6), "image/png"));
  show("malformed JSON curve", c->Post("/api/sketch/curves", "{\"points\": [[0, 0", "application/json"));
  show("format ../../etc/passwd", c->Post("/api/uploads/mesh?format=../../etc/passwd", "x", "text/plain"));
  show("upload name ../../x", c->Post("/api/uploads/mesh?format=exe&name=../../x", "x", "text/plain"));
  show("GET /../../etc/passwd", c->Get("/../../etc/passwd"));
  show("GET /vendor/three/../../../../etc/passwd", c->Get("/vendor/three/../../../../etc/passwd"));
  show("unknown curve id", c->Delete("/api/sketch/curves/curve-424242"));
  show("cut at position 7", c->Post("/api/cut", "{\"axis\": \"x\", \"position\": 7}", "application/json"));
  show("health afterwards", c->Get("/api/health"));
}

}  // namespace

int main(int argc, char** argv) {
  if (argc < 4) {
    std::fprintf(stderr, "usage: studio_load PORT SERVER_PID SKETCH.json [--clients N] [--seconds S] [--phases P]\n");
    return 2;
  }
  port = std::stoi(argv[1]);
  const int pid = std::stoi(argv[2]);
  std::ifstream in(argv[3]);
  const json sketch = json::parse(in);
  int clients = 50, seconds = 60, phases = 2;
  for (int i = 4; i + 1 < argc; i += 2) {
    if (std::string(argv[i]) == "--clients") clients = std::stoi(argv[i + 1]);
    if (std::string(argv[i]) == "--seconds") seconds = std::stoi(argv[i + 1]);
    if (std::string(argv[i]) == "--phases") phases = std::stoi(argv[i + 1]);
  }
  EventReader events;
  latencies(sketch, events);
  load(sketch, clients, seconds, phases, pid);
  badInput();
  return 0;
}
