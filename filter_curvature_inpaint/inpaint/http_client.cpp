#include "http_client.h"

#include <vcg_ext/mesh_errors.h>

#include <curl/curl.h>

#include <algorithm>
#include <cctype>
#include <chrono>
#include <cmath>
#include <mutex>
#include <thread>

namespace curvature_inpaint {

namespace {

struct Transfer {
  std::string body;
  std::map<std::string, std::string> headers;
  size_t cap = 0;
  bool over_cap = false;
  const HttpOptions* options = nullptr;
};

size_t OnBody(char* data, size_t size, size_t count, void* user) {
  auto* t = static_cast<Transfer*>(user);
  const size_t n = size * count;
  if (t->body.size() + n > t->cap) {
    t->over_cap = true;
    return 0; // aborts the transfer
  }
  t->body.append(data, n);
  return n;
}

size_t OnHeader(char* data, size_t size, size_t count, void* user) {
  auto* t = static_cast<Transfer*>(user);
  const std::string line(data, size * count);
  const auto colon = line.find(':');
  if (colon != std::string::npos) {
    std::string name = line.substr(0, colon);
    std::transform(name.begin(), name.end(), name.begin(),
                   [](unsigned char c) { return char(std::tolower(c)); });
    std::string value = line.substr(colon + 1);
    value.erase(0, value.find_first_not_of(" \t"));
    value.erase(value.find_last_not_of(" \t\r\n") + 1);
    t->headers[name] = value;
  }
  return size * count;
}

int OnProgress(void* user, curl_off_t, curl_off_t, curl_off_t, curl_off_t) {
  auto* t = static_cast<Transfer*>(user);
  return t->options->cancelled && t->options->cancelled() ? 1 : 0;
}

void GlobalInit() {
  static std::once_flag once;
  std::call_once(once, [] { curl_global_init(CURL_GLOBAL_DEFAULT); });
}

HttpResponse SendOnce(const HttpRequest& request, const HttpOptions& options) {
  GlobalInit();
  CURL* curl = curl_easy_init();
  if (!curl) throw HttpError("libcurl could not start a transfer");
  Transfer t;
  t.cap = options.max_response_bytes;
  t.options = &options;
  curl_slist* headers = nullptr;
  for (const auto& h : request.headers) headers = curl_slist_append(headers, h.c_str());
  curl_mime* mime = nullptr;
  curl_easy_setopt(curl, CURLOPT_URL, request.url.c_str());
  curl_easy_setopt(curl, CURLOPT_FOLLOWLOCATION, 0L);
  curl_easy_setopt(curl, CURLOPT_SSL_VERIFYPEER, 1L);
  curl_easy_setopt(curl, CURLOPT_SSL_VERIFYHOST, 2L);
  curl_easy_setopt(curl, CURLOPT_NOSIGNAL, 1L);
  curl_easy_setopt(curl, CURLOPT_CONNECTTIMEOUT_MS, long(options.connect_timeout_s * 1000));
  curl_easy_setopt(curl, CURLOPT_TIMEOUT_MS, long(options.total_timeout_s * 1000));
  curl_easy_setopt(curl, CURLOPT_MAXFILESIZE_LARGE, curl_off_t(options.max_response_bytes));
  curl_easy_setopt(curl, CURLOPT_WRITEFUNCTION, OnBody);
  curl_easy_setopt(curl, CURLOPT_WRITEDATA, &t);
  curl_easy_setopt(curl, CURLOPT_HEADERFUNCTION, OnHeader);
  curl_easy_setopt(curl, CURLOPT_HEADERDATA, &t);
  curl_easy_setopt(curl, CURLOPT_NOPROGRESS, 0L);
  curl_easy_setopt(curl, CURLOPT_XFERINFOFUNCTION, OnProgress);
  curl_easy_setopt(curl, CURLOPT_XFERINFODATA, &t);
  curl_easy_setopt(curl, CURLOPT_USERAGENT, "curvature-inpaint/0.1");
  if (!request.parts.empty()) {
    mime = curl_mime_init(curl);
    for (const auto& p : request.parts) {
      curl_mimepart* part = curl_mime_addpart(mime);
      curl_mime_name(part, p.name.c_str());
      curl_mime_data(part, p.data.data(), p.data.size());
      if (!p.filename.empty()) curl_mime_filename(part, p.filename.c_str());
      if (!p.content_type.empty()) curl_mime_type(part, p.content_type.c_str());
    }
    curl_easy_setopt(curl, CURLOPT_MIMEPOST, mime);
  } else if (request.method == "POST") {
    curl_easy_setopt(curl, CURLOPT_POSTFIELDS, request.body.data());
    curl_easy_setopt(curl, CURLOPT_POSTFIELDSIZE_LARGE, curl_off_t(request.body.size()));
  }
  if (request.method != "GET" && request.method != "POST")
    curl_easy_setopt(curl, CURLOPT_CUSTOMREQUEST, request.method.c_str());
  curl_easy_setopt(curl, CURLOPT_HTTPHEADER, headers);
  const CURLcode rc = curl_easy_perform(curl);
  HttpResponse response;
  curl_easy_getinfo(curl, CURLINFO_RESPONSE_CODE, &response.status);
  curl_mime_free(mime);
  curl_slist_free_all(headers);
  curl_easy_cleanup(curl);
  if (t.over_cap || rc == CURLE_FILESIZE_EXCEEDED)
    throw HttpError("the response was larger than " +
                    std::to_string(options.max_response_bytes >> 20) + " MB and was refused");
  if (rc == CURLE_ABORTED_BY_CALLBACK) throw vcg_ext::CancelledError();
  if (rc == CURLE_OPERATION_TIMEDOUT)
    throw HttpError("no complete answer within " + std::to_string(int(options.total_timeout_s)) +
                    " s");
  if (rc != CURLE_OK) throw HttpError(curl_easy_strerror(rc));
  response.headers = std::move(t.headers);
  response.body = std::move(t.body);
  return response;
}

bool Retryable(long status) {
  return status == 408 || status == 409 || status == 429 || status >= 500;
}

double RetryWait(const HttpResponse& r, double fallback, double max_wait) {
  auto ms = r.headers.find("retry-after-ms");
  if (ms != r.headers.end()) {
    const double v = std::atof(ms->second.c_str()) / 1000.0;
    if (v >= 0 && std::isfinite(v)) return std::min(v, max_wait);
  }
  auto s = r.headers.find("retry-after");
  if (s != r.headers.end()) {
    char* end = nullptr;
    const double v = std::strtod(s->second.c_str(), &end);
    if (end != s->second.c_str() && v >= 0 && std::isfinite(v)) return std::min(v, max_wait);
  }
  return fallback;
}

} // namespace

HttpResponse SendWithRetries(const HttpRequest& request, const HttpOptions& options) {
  double backoff = options.backoff_s;
  for (int attempt = 0;; ++attempt) {
    HttpResponse r = options.transport ? options.transport(request) : SendOnce(request, options);
    if (!Retryable(r.status) || attempt >= options.max_retries) return r;
    const double wait = RetryWait(r, backoff, options.max_wait_s);
    backoff *= 2;
    const auto until = std::chrono::steady_clock::now() + std::chrono::duration<double>(wait);
    while (std::chrono::steady_clock::now() < until) {
      if (options.cancelled && options.cancelled()) throw vcg_ext::CancelledError();
      std::this_thread::sleep_for(std::chrono::milliseconds(20));
    }
  }
}

} // namespace curvature_inpaint
