// The HTTP layer of the remote inpainting backends, over libcurl: connect and total timeouts,
// retries with backoff on 408/409/429/5xx honouring retry-after-ms and retry-after, TLS
// verification on, proxies from the usual environment variables (libcurl reads them), no
// redirects followed, a cap on the response size, and cancellation. Header values (API keys)
// never appear in any message this layer produces.
#pragma once

#include <functional>
#include <map>
#include <stdexcept>
#include <string>
#include <vector>

namespace curvature_inpaint {

struct HttpPart {
  std::string name;
  std::string data;
  std::string filename;     ///< non-empty: sent as a file
  std::string content_type; ///< e.g. image/png
};

struct HttpRequest {
  std::string method = "GET";
  std::string url;
  std::vector<std::string> headers; ///< "Name: value"
  std::string body;                 ///< raw body (with a Content-Type header)
  std::vector<HttpPart> parts;      ///< multipart/form-data body, used when not empty
};

struct HttpResponse {
  long status = 0;
  std::map<std::string, std::string> headers; ///< lower-case names
  std::string body;
};

struct HttpOptions {
  double connect_timeout_s = 10;
  double total_timeout_s = 300; ///< per attempt
  size_t max_response_bytes = 64u << 20;
  int max_retries = 3;
  double backoff_s = 1.0; ///< first wait without retry-after; doubles each retry
  double max_wait_s = 60; ///< longest wait honoured from retry-after
  /// Polled during transfers and retry waits; true stops with vcg_ext::CancelledError.
  std::function<bool()> cancelled;
  /// Replaces the network for one attempt (the fuzz targets feed the backends' response
  /// handling through it); empty: libcurl.
  std::function<HttpResponse(const HttpRequest&)> transport;
};

/// A transfer that did not produce an HTTP response (connection, timeout, size cap).
class HttpError : public std::runtime_error {
public:
  explicit HttpError(const std::string& what) : std::runtime_error(what) {}
};

/// Sends `request`, retrying on 408/409/429/5xx as `options` say; returns the last response
/// (which may still be an error status). Throws HttpError when no response arrives, and
/// vcg_ext::CancelledError when `options.cancelled` asks to stop: a stop is no failure of the
/// service, so callers that retry elsewhere or report a service error let it pass.
HttpResponse SendWithRetries(const HttpRequest& request, const HttpOptions& options);

} // namespace curvature_inpaint
