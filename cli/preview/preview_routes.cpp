#include "preview_routes.h"

#include "preview_page.h"
#include "preview_token.h"

namespace lucent::preview {

bool BoardStream::next(std::string& text) {
  if (!board_.collect(cursor_, std::chrono::milliseconds(1000), text)) return false;
  if (text.empty()) text = ": still here\n\n";
  return true;
}

namespace {

HttpReply save(const LastImage& last) {
  HttpReply reply;
  if (!last.save(reply.body)) reply.status = 409;
  return reply;
}

HttpReply setControl(const HttpRequest& request, const PreviewPlaces& places) {
  HttpReply reply;
  const auto name = request.query.find("name"), value = request.query.find("value");
  if (name == request.query.end() || value == request.query.end()) {
    reply.status = 400;
    reply.body = "/set needs name and value";
    return reply;
  }
  reply.body = places.controls.set(name->second, value->second);
  if (!reply.body.empty()) {
    reply.status = 400;
    return reply;
  }
  places.changed();
  return reply;
}

HttpReply setRegion(const HttpRequest& request, const PreviewPlaces& places) {
  HttpReply reply;
  const auto region = request.query.find("region");
  reply.body = places.controls.setRegion(region == request.query.end() ? "" : region->second);
  if (!reply.body.empty()) {
    reply.status = 400;
    return reply;
  }
  places.changed();
  return reply;
}

}  // namespace

HttpHandler previewRoutes(const std::string& token, PreviewPlaces places) {
  return [token, places](const HttpRequest& request) {
    HttpReply reply;
    reply.headers.emplace_back("Cache-Control", "no-store");
    const auto given = request.query.find("token");
    if (given == request.query.end() || !tokenAccepted(given->second, token)) {
      reply.status = 403;
      reply.body = "403 forbidden: use the address lucent preview printed (with its token)\n";
      return reply;
    }
    if (request.method == "POST") {
      // Only the button's request changes anything; a link cannot (it would be a GET).
      if (request.path == "/save") return save(places.last);
      if (request.path == "/set") return setControl(request, places);
      if (request.path == "/region") return setRegion(request, places);
      reply.status = 404;
      reply.body = "404 not found\n";
    } else if (request.path == "/") {
      reply.contentType = "text/html; charset=utf-8";
      reply.body = previewPage();
      // The page reaches nothing but this server: no script, style or image from elsewhere.
      reply.headers.emplace_back("Content-Security-Policy",
                                 "default-src 'none'; connect-src 'self'; img-src data:; "
                                 "style-src 'unsafe-inline'; script-src 'unsafe-inline'");
    } else if (request.path == "/events") {
      reply.contentType = "text/event-stream";
      reply.stream = std::make_shared<BoardStream>(places.board);
    } else {
      reply.status = 404;
      reply.body = "404 not found\n";
    }
    return reply;
  };
}

}  // namespace lucent::preview
