// The preview's web server on cpp-httplib: the only code that includes its header or links
// its library (http_server.h says why it is a plugin).
#include "../http_server.h"

#include <httplib.h>

#include <cerrno>
#include <cstring>
#include <thread>

#include <sys/socket.h>

namespace lucent::preview {

namespace {

// Connections served at once: the page's event stream holds one for as long as it is open,
// so a few pages and their reloads need more than the default's eight on a small machine.
constexpr size_t kConnectionThreads = 16;

class HttplibServer : public HttpServer {
 public:
  explicit HttplibServer(HttpHandler handler) : handler_(std::move(handler)) {
    server_.new_task_queue = [] { return new httplib::ThreadPool(kConnectionThreads); };
    server_.set_keep_alive_timeout(1);
    // SO_REUSEADDR only: httplib's default adds SO_REUSEPORT, with which a second preview
    // would share a port in use instead of being told it is.
    server_.set_socket_options([](socket_t socket) {
      int yes = 1;
      ::setsockopt(socket, SOL_SOCKET, SO_REUSEADDR, &yes, sizeof yes);
    });
    auto serve = [this](const httplib::Request& request, httplib::Response& response) {
      this->serve(request, response);
    };
    server_.Get(".*", serve);
    server_.Post(".*", serve);
  }
  ~HttplibServer() override { stop(); }

  // "" or why the address cannot be listened on.
  std::string listen(const std::string& host, int port) {
    errno = 0;
    port_ =
        port == 0 ? server_.bind_to_any_port(host) : (server_.bind_to_port(host, port) ? port : -1);
    if (port_ <= 0) return errno != 0 ? std::strerror(errno) : "the address cannot be used";
    thread_ = std::thread([this] { server_.listen_after_bind(); });
    return "";
  }

  int port() const override { return port_; }

  void stop() override {
    if (!thread_.joinable()) return;
    server_.stop();
    thread_.join();
  }

 private:
  void serve(const httplib::Request& request, httplib::Response& response) {
    HttpRequest r;
    r.method = request.method;
    r.path = request.path;
    for (const auto& [name, value] : request.params) r.query.emplace(name, value);
    HttpReply reply = handler_(r);
    response.status = reply.status;
    for (const auto& [name, value] : reply.headers) response.set_header(name, value);
    if (!reply.stream) {
      response.set_content(reply.body, reply.contentType);
      return;
    }
    response.set_chunked_content_provider(
        reply.contentType, [stream = reply.stream](size_t, httplib::DataSink& sink) {
          std::string text;
          if (!stream->next(text)) {
            sink.done();
            return true;
          }
          return text.empty() || sink.write(text.data(), text.size());
        });
  }

  HttpHandler handler_;
  httplib::Server server_;
  std::thread thread_;
  int port_ = -1;
};

}  // namespace

}  // namespace lucent::preview

extern "C" __attribute__((visibility("default"))) lucent::preview::HttpServer*
lucent_preview_server_start_v1(const lucent::preview::HttpServerSetup& setup, std::string& error) {
  auto server = std::make_unique<lucent::preview::HttplibServer>(setup.handler);
  error = server->listen(setup.host, setup.port);
  return error.empty() ? server.release() : nullptr;
}
