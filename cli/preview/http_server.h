// The preview's web server behind a plugin (lucent-preview-server.so, server/), loaded by
// `lucent preview` alone, so that every other command neither links nor loads cpp-httplib
// (and the OpenSSL, zlib and Brotli libraries Debian builds it with). What is served is
// decided here, in `lucent` (preview_routes.h): the plugin only carries requests and
// replies. It is built by the same compiler from the same tree, so C++ types cross the
// boundary safely (as images/image_plugin.h's do).
#pragma once

#include <functional>
#include <map>
#include <memory>
#include <string>
#include <utility>
#include <vector>

namespace lucent::preview {

struct HttpRequest {
  std::string method;  // GET or POST
  std::string path;
  std::map<std::string, std::string> query;
};

// A reply sent as it is made (server-sent events): the connection stays open while next()
// returns true.
class EventStream {
 public:
  virtual ~EventStream() = default;
  // The next text to send ("" to send nothing yet); waits a little for it. False: end.
  virtual bool next(std::string& text) = 0;
};

struct HttpReply {
  int status = 200;
  std::string contentType = "text/plain; charset=utf-8";
  std::string body;
  std::shared_ptr<EventStream> stream;  // set: the body is this stream
  std::vector<std::pair<std::string, std::string>> headers;
};

using HttpHandler = std::function<HttpReply(const HttpRequest&)>;

struct HttpServerSetup {
  std::string host;  // the address to listen on
  int port = 0;      // 0: any free port
  HttpHandler handler;
};

// A server listening (on its own threads) until stop() or its end.
class HttpServer {
 public:
  virtual ~HttpServer() = default;
  virtual int port() const = 0;
  // Closes the listening socket and waits for the connections' threads (each stream must
  // end: its next() returns false).
  virtual void stop() = 0;
};

// Starts a server (found beside the `lucent` program, loaded on first use). Throws
// std::runtime_error saying why it cannot: the plugin cannot be loaded, or the address
// cannot be listened on (the port in use, an address not of this machine).
std::unique_ptr<HttpServer> startHttpServer(const HttpServerSetup& setup);

}  // namespace lucent::preview

// The plugin's one exported function: a started server, or null with `error` set.
#define LUCENT_PREVIEW_SERVER_ENTRY "lucent_preview_server_start_v1"
using LucentPreviewServerEntry =
    lucent::preview::HttpServer* (*)(const lucent::preview::HttpServerSetup& setup,
                                     std::string& error);
