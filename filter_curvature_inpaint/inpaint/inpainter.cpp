#include "inpainter.h"

#include "server_pool.h"

#include "pipeline/fill_settings.h"

#include <vcg_ext/mesh_errors.h>

#include <QBuffer>
#include <QByteArray>
#include <QFile>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QRegularExpression>
#include <QUrl>

#include <algorithm>
#include <chrono>

#include <cstdlib>
#include <map>
#include <thread>

namespace curvature_inpaint {

namespace {

const char* const kDallePrompt = "fill in the blanks";
const char* const kDiffusionPrompt =
    "Color map representing curvatures made by green, red, and blue gradient zones, match the "
    "surroundings, diffuse colors";

std::string Env(const char* name) {
  const char* v = std::getenv(name);
  return v ? std::string(v) : std::string();
}

/// Removes anything that looks like a secret from a service's message before it is shown.
std::string Redact(std::string text) {
  for (const char* var : {"OPENAI_API_KEY", "STABILITY_API_KEY", "SD_WEBUI_AUTH"}) {
    const std::string key = Env(var);
    if (key.size() < 4) continue;
    for (size_t at; (at = text.find(key)) != std::string::npos;)
      text.replace(at, key.size(), "[key]");
  }
  static const QRegularExpression token("(sk|key)-[A-Za-z0-9_*\\-]{6,}");
  return QString::fromStdString(text).replace(token, "[key]").toStdString();
}

std::string Png(const QImage& image) {
  QByteArray bytes;
  QBuffer buffer(&bytes);
  buffer.open(QIODevice::WriteOnly);
  image.save(&buffer, "PNG");
  return bytes.toStdString();
}

QImage DecodePng(const QByteArray& data, const std::string& backend) {
  QImage img;
  // A decompression bomb declares a huge size in a small file: refuse before decoding.
  if (data.size() >= 24 && data.startsWith("\x89PNG")) {
    const auto* d = reinterpret_cast<const unsigned char*>(data.constData());
    const quint64 w = (quint64(d[16]) << 24) | (d[17] << 16) | (d[18] << 8) | d[19];
    const quint64 h = (quint64(d[20]) << 24) | (d[21] << 16) | (d[22] << 8) | d[23];
    if (w * h > 8192ull * 8192ull)
      throw InpaintError(backend + ": the service returned an image of " + std::to_string(w) + "x" +
                         std::to_string(h) + " pixels, which was refused");
  }
  if (!img.loadFromData(data))
    throw InpaintError(backend + ": the service returned an image that is not a valid PNG");
  return img.convertToFormat(QImage::Format_RGB32);
}

QImage DecodeBase64Png(const QJsonValue& v, const std::string& backend) {
  if (!v.isString()) throw InpaintError(backend + ": the answer holds no image data");
  const QByteArray raw = v.toString().toLatin1();
  auto decoded = QByteArray::fromBase64Encoding(raw, QByteArray::AbortOnBase64DecodingErrors);
  if (!decoded) throw InpaintError(backend + ": the answer holds invalid base64 image data");
  return DecodePng(*decoded, backend);
}

/// The service's own words for an error, from the shapes the services use.
std::string ServiceMessage(const std::string& body) {
  const QJsonDocument doc = QJsonDocument::fromJson(QByteArray::fromStdString(body));
  if (doc.isObject()) {
    const QJsonObject o = doc.object();
    if (o.value("error").isObject()) {
      const QJsonObject e = o.value("error").toObject();
      if (e.value("message").isString()) return e.value("message").toString().toStdString();
    }
    if (o.value("detail").isString()) return o.value("detail").toString().toStdString();
    if (o.value("detail").isArray()) {
      std::string out;
      for (const auto& d : o.value("detail").toArray()) {
        const QString msg = d.toObject().value("msg").toString();
        if (!msg.isEmpty()) out += (out.empty() ? "" : "; ") + msg.toStdString();
      }
      if (!out.empty()) return out;
    }
    if (o.value("errors").isArray()) {
      std::string out;
      for (const auto& e : o.value("errors").toArray())
        if (e.isString()) out += (out.empty() ? "" : "; ") + e.toString().toStdString();
      if (!out.empty()) return out;
    }
    if (o.value("error").isString()) return o.value("error").toString().toStdString();
    if (o.value("message").isString()) return o.value("message").toString().toStdString();
  }
  return "no message";
}

QJsonObject JsonBody(const HttpResponse& r, const std::string& backend) {
  QJsonParseError err;
  const QJsonDocument doc = QJsonDocument::fromJson(QByteArray::fromStdString(r.body), &err);
  if (err.error != QJsonParseError::NoError || !doc.isObject())
    throw InpaintError(backend + ": the service's answer (HTTP " + std::to_string(r.status) +
                       ") is not the JSON it should be");
  return doc.object();
}

HttpResponse Call(const HttpRequest& req, const InpaintParams& p, const std::string& backend) {
  HttpResponse r;
  try {
    r = SendWithRetries(req, p.http);
  } catch (const HttpError& e) {
    throw InpaintError(backend + ": " + Redact(e.what()));
  }
  // A redirect may lead the request, key included, to another host: never followed.
  if (r.status >= 300 && r.status < 400)
    throw InpaintError(backend + ": HTTP " + std::to_string(r.status) +
                       ": the service redirects elsewhere; redirects are not followed, give its "
                       "final address");
  if (r.status < 200 || r.status >= 300)
    throw InpaintError(backend + ": HTTP " + std::to_string(r.status) + ": " +
                       Redact(ServiceMessage(r.body)));
  return r;
}

std::string Trimmed(std::string url) {
  while (!url.empty() && url.back() == '/') url.pop_back();
  return url;
}

void ExpectSize(const QImage& img, int w, int h, const std::string& backend) {
  if (img.width() != w || img.height() != h)
    throw InpaintError(backend + ": the service returned a " + std::to_string(img.width()) + "x" +
                       std::to_string(img.height()) + " image where " + std::to_string(w) + "x" +
                       std::to_string(h) + " was asked");
}

QImage MaskWhiteOnBlack(const QImage& mask) {
  QImage m(mask.size(), QImage::Format_RGB32);
  for (int y = 0; y < mask.height(); ++y)
    for (int x = 0; x < mask.width(); ++x)
      m.setPixel(x, y, qGray(mask.pixel(x, y)) > 127 ? qRgb(255, 255, 255) : qRgb(0, 0, 0));
  return m;
}

QImage WithTransparentHole(const QImage& image, const QImage& mask) {
  QImage out = image.convertToFormat(QImage::Format_ARGB32);
  for (int y = 0; y < out.height(); ++y)
    for (int x = 0; x < out.width(); ++x)
      if (qGray(mask.pixel(x, y)) > 127) out.setPixel(x, y, qRgba(0, 0, 0, 0));
  return out;
}

QImage Scaled(const QImage& img, int w, int h) {
  return img.size() == QSize(w, h)
             ? img
             : img.scaled(w, h, Qt::IgnoreAspectRatio, Qt::SmoothTransformation);
}

// --- the services -----------------------------------------------------------------------

std::vector<QImage> OpenAi(const QImage& image, const QImage& mask, const InpaintParams& p) {
  const std::string backend = BackendName(Backend::kOpenAi);
  const std::string key = Env("OPENAI_API_KEY");
  if (key.empty()) throw InpaintError(backend + ": set OPENAI_API_KEY to the API key to use");
  const std::string model =
      p.model.empty() ? DescribeBackend(Backend::kOpenAi).default_model : p.model;
  if (model != "dall-e-2" && model != "gpt-image-1")
    throw InpaintError(backend + ": unknown model \"" + model + "\" (dall-e-2 or gpt-image-1)");
  int size = 1024;
  if (model == "dall-e-2") {
    const int want = p.size > 0 ? p.size : std::max(image.width(), image.height());
    size = want <= 256 ? 256 : want <= 512 ? 512 : 1024;
  }
  const QImage rgba = WithTransparentHole(Scaled(image, size, size), Scaled(mask, size, size));
  HttpRequest req;
  req.method = "POST";
  req.url = Trimmed(p.url.empty() ? (Env("OPENAI_BASE_URL").empty()
                                         ? DescribeBackend(Backend::kOpenAi).default_url
                                         : Env("OPENAI_BASE_URL"))
                                  : p.url) +
            "/images/edits";
  req.headers = {"Authorization: Bearer " + key};
  const std::string png = Png(rgba);
  const std::string sz = std::to_string(size) + "x" + std::to_string(size);
  req.parts = {{"image", png, "image.png", "image/png"},
               {"mask", png, "mask.png", "image/png"},
               {"prompt", p.prompt.empty() ? kDallePrompt : p.prompt, "", ""},
               {"model", model, "", ""},
               {"n", std::to_string(std::max(1, std::min(10, p.variations))), "", ""},
               {"size", sz, "", ""}};
  if (model == "dall-e-2") req.parts.push_back({"response_format", "b64_json", "", ""});
  const QJsonObject o = JsonBody(Call(req, p, backend), backend);
  std::vector<QImage> out;
  for (const auto& d : o.value("data").toArray()) {
    QImage img = DecodeBase64Png(d.toObject().value("b64_json"), backend);
    ExpectSize(img, size, size, backend);
    out.push_back(img);
  }
  if (out.empty()) throw InpaintError(backend + ": the answer holds no images");
  return out;
}

std::vector<QImage> SdWebUi(const QImage& image, const QImage& mask, const InpaintParams& p) {
  const std::string backend = BackendName(Backend::kSdWebUi);
  const int size = std::max(64, (p.size > 0 ? p.size : 512) / 8 * 8);
  QJsonObject body;
  body["init_images"] = QJsonArray{
      QString::fromLatin1(QByteArray::fromStdString(Png(Scaled(image, size, size))).toBase64())};
  body["mask"] = QString::fromLatin1(
      QByteArray::fromStdString(Png(MaskWhiteOnBlack(Scaled(mask, size, size)))).toBase64());
  body["mask_blur"] = 4;
  body["inpainting_fill"] = 1;
  body["inpaint_full_res"] = false;
  body["inpainting_mask_invert"] = 0;
  body["denoising_strength"] = 0.75;
  body["prompt"] = QString::fromStdString(p.prompt.empty() ? kDiffusionPrompt : p.prompt);
  body["negative_prompt"] = QString::fromStdString(p.negative_prompt);
  body["seed"] = double(p.seed);
  body["steps"] = 30;
  body["cfg_scale"] = 7;
  body["width"] = size;
  body["height"] = size;
  body["batch_size"] = std::max(1, p.variations);
  body["n_iter"] = 1;
  body["sampler_name"] = "Euler a";
  HttpRequest req;
  req.method = "POST";
  req.url = Trimmed(p.url.empty() ? DescribeBackend(Backend::kSdWebUi).default_url : p.url) +
            "/sdapi/v1/img2img";
  req.headers = {"Content-Type: application/json"};
  const std::string auth = Env("SD_WEBUI_AUTH");
  if (!auth.empty())
    req.headers.push_back("Authorization: Basic " +
                          QByteArray::fromStdString(auth).toBase64().toStdString());
  req.body = QJsonDocument(body).toJson(QJsonDocument::Compact).toStdString();
  const QJsonObject o = JsonBody(Call(req, p, backend), backend);
  std::vector<QImage> out;
  for (const auto& v : o.value("images").toArray()) {
    QImage img = DecodeBase64Png(v, backend);
    ExpectSize(img, size, size, backend);
    out.push_back(img);
  }
  if (out.empty()) throw InpaintError(backend + ": the answer holds no images");
  // Some versions append extra images (masks, grids) after the batch.
  if (int(out.size()) > p.variations) out.resize(p.variations);
  return out;
}

std::vector<QImage> Stability(const QImage& image, const QImage& mask, const InpaintParams& p) {
  const std::string backend = BackendName(Backend::kStability);
  const std::string key = Env("STABILITY_API_KEY");
  if (key.empty()) throw InpaintError(backend + ": set STABILITY_API_KEY to the API key to use");
  const int w = image.width(), h = image.height();
  std::vector<QImage> out;
  for (int i = 0; i < std::max(1, p.variations); ++i) {
    HttpRequest req;
    req.method = "POST";
    req.url = Trimmed(p.url.empty() ? DescribeBackend(Backend::kStability).default_url : p.url) +
              "/v2beta/stable-image/edit/inpaint";
    req.headers = {"authorization: Bearer " + key, "accept: application/json"};
    req.parts = {
        {"image", Png(image.convertToFormat(QImage::Format_RGB32)), "image.png", "image/png"},
        {"mask", Png(MaskWhiteOnBlack(mask)), "mask.png", "image/png"},
        {"prompt", p.prompt.empty() ? kDiffusionPrompt : p.prompt, "", ""},
        {"seed", std::to_string((p.seed + i) % 4294967295u), "", ""},
        {"output_format", "png", "", ""}};
    if (!p.negative_prompt.empty())
      req.parts.push_back({"negative_prompt", p.negative_prompt, "", ""});
    const QJsonObject o = JsonBody(Call(req, p, backend), backend);
    QImage img = DecodeBase64Png(o.value("image"), backend);
    ExpectSize(img, w, h, backend);
    out.push_back(img);
  }
  return out;
}

// The workflow shipped with the product (comfyui_inpaint_workflow.json, compiled in), or the
// user's edited copy.
std::string WorkflowTemplate(const std::string& file) {
  static const char* const kBuiltIn =
#include "comfyui_inpaint_workflow.inc"
      ;
  if (file.empty()) return kBuiltIn;
  QFile f(QString::fromStdString(file));
  if (!f.open(QIODevice::ReadOnly)) throw InpaintError("comfyui: cannot read the workflow " + file);
  return f.readAll().toStdString();
}

QString JsonString(const std::string& s) {
  return QJsonDocument(QJsonArray{QString::fromStdString(s)})
      .toJson(QJsonDocument::Compact)
      .mid(1)
      .chopped(1);
}

std::vector<QImage> ComfyUi(const QImage& image, const QImage& mask, const InpaintParams& p) {
  const std::string backend = BackendName(Backend::kComfyUi);
  const std::string base =
      Trimmed(p.url.empty() ? DescribeBackend(Backend::kComfyUi).default_url : p.url);
  const int size = std::max(64, (p.size > 0 ? p.size : 512) / 8 * 8);
  auto upload = [&](const QImage& img, const std::string& name) {
    HttpRequest req;
    req.method = "POST";
    req.url = base + "/upload/image";
    req.parts = {{"image", Png(img), name, "image/png"},
                 {"type", "input", "", ""},
                 {"overwrite", "true", "", ""}};
    const QJsonObject o = JsonBody(Call(req, p, backend), backend);
    if (!o.value("name").isString())
      throw InpaintError(backend + ": the upload answer names no file");
    return o.value("name").toString().toStdString();
  };
  const std::string image_name =
      upload(Scaled(image, size, size).convertToFormat(QImage::Format_RGB32), "curvature.png");
  const std::string mask_name =
      upload(MaskWhiteOnBlack(Scaled(mask, size, size)), "curvature_mask.png");
  std::vector<QImage> out;
  for (int i = 0; i < std::max(1, p.variations); ++i) {
    QString wf = QString::fromStdString(WorkflowTemplate(p.workflow_file));
    wf.replace("\"{{IMAGE}}\"", JsonString(image_name));
    wf.replace("\"{{MASK}}\"", JsonString(mask_name));
    wf.replace("\"{{PROMPT}}\"", JsonString(p.prompt.empty() ? kDiffusionPrompt : p.prompt));
    wf.replace("\"{{NEGATIVE_PROMPT}}\"", JsonString(p.negative_prompt));
    wf.replace("\"{{SEED}}\"", QString::number(qulonglong(p.seed) + i));
    QJsonParseError err;
    const QJsonDocument graph = QJsonDocument::fromJson(wf.toUtf8(), &err);
    if (err.error != QJsonParseError::NoError)
      throw InpaintError(backend + ": the workflow template is not valid JSON");
    HttpRequest req;
    req.method = "POST";
    req.url = base + "/prompt";
    req.headers = {"Content-Type: application/json"};
    QJsonObject body;
    body["prompt"] = graph.object();
    body["client_id"] = "curvature-inpaint";
    req.body = QJsonDocument(body).toJson(QJsonDocument::Compact).toStdString();
    const QJsonObject queued = JsonBody(Call(req, p, backend), backend);
    const QString id = queued.value("prompt_id").toString();
    if (id.isEmpty()) throw InpaintError(backend + ": the queue answer holds no prompt_id");
    // Poll the history until the prompt has outputs.
    QJsonObject outputs;
    const auto deadline =
        std::chrono::steady_clock::now() + std::chrono::duration<double>(p.http.total_timeout_s);
    for (;;) {
      HttpRequest poll;
      poll.url = base + "/history/" + id.toStdString();
      const QJsonObject history = JsonBody(Call(poll, p, backend), backend);
      const QJsonObject entry = history.value(id).toObject();
      if (entry.value("outputs").isObject() && !entry.value("outputs").toObject().isEmpty()) {
        outputs = entry.value("outputs").toObject();
        break;
      }
      if (std::chrono::steady_clock::now() > deadline)
        throw InpaintError(backend + ": the prompt did not finish within " +
                           std::to_string(int(p.http.total_timeout_s)) + " s");
      if (p.http.cancelled && p.http.cancelled()) throw vcg_ext::CancelledError();
      std::this_thread::sleep_for(std::chrono::milliseconds(200));
    }
    for (const auto& node : outputs)
      for (const auto& im : node.toObject().value("images").toArray()) {
        const QJsonObject f = im.toObject();
        HttpRequest view;
        view.url =
            base + "/view?filename=" +
            QUrl::toPercentEncoding(f.value("filename").toString()).toStdString() +
            "&subfolder=" + QUrl::toPercentEncoding(f.value("subfolder").toString()).toStdString() +
            "&type=" + QUrl::toPercentEncoding(f.value("type").toString()).toStdString();
        const HttpResponse r = Call(view, p, backend);
        QImage img = DecodePng(QByteArray::fromStdString(r.body), backend);
        ExpectSize(img, size, size, backend);
        out.push_back(img);
      }
  }
  if (out.empty()) throw InpaintError(backend + ": the workflow produced no images");
  return out;
}

} // namespace

const std::vector<Backend>& InpaintBackends() {
  static const std::vector<Backend> backends{Backend::kEmbedded, Backend::kOpenAi,
                                             Backend::kSdWebUi, Backend::kStability,
                                             Backend::kComfyUi};
  return backends;
}

Backend BackendAt(int index) {
  const std::vector<Backend>& backends = InpaintBackends();
  return backends[size_t(std::max(0, std::min(int(backends.size()) - 1, index)))];
}

std::string BackendName(Backend backend) {
  switch (backend) {
  case Backend::kEmbedded:
    return "embedded";
  case Backend::kOpenAi:
    return "openai";
  case Backend::kSdWebUi:
    return "sd-webui";
  case Backend::kStability:
    return "stability";
  case Backend::kComfyUi:
    return "comfyui";
  }
  return "embedded";
}

Backend ParseBackend(const std::string& name) {
  std::string known;
  for (Backend b : InpaintBackends()) {
    if (BackendName(b) == name) return b;
    known += (known.empty() ? "" : ", ") + BackendName(b);
  }
  throw vcg_ext::InvalidParameterError("unknown backend \"" + name + "\" (" + known + ")");
}

const BackendInfo& DescribeBackend(Backend backend) {
  static const std::map<Backend, BackendInfo> info{
      {Backend::kEmbedded, {"", "", false, "", false, false}},
      {Backend::kOpenAi,
       {"https://api.openai.com/v1", "OPENAI_API_KEY", true, "dall-e-2", true, false}},
      {Backend::kSdWebUi, {"http://127.0.0.1:7860", "SD_WEBUI_AUTH", false, "", true, true}},
      {Backend::kStability,
       {"https://api.stability.ai", "STABILITY_API_KEY", true, "", true, true}},
      {Backend::kComfyUi, {"http://127.0.0.1:8188", "", false, "", true, true}}};
  return info.at(backend);
}

std::string DefaultPrompt(Backend backend) {
  if (backend == Backend::kOpenAi) return kDallePrompt;
  if (backend == Backend::kEmbedded) return "";
  return kDiffusionPrompt;
}

void CheckInpaintParams(const InpaintParams& p) {
  using vcg_ext::RequireRange;
  RequireSetting(Setting::kVariations, p.variations);
  RequireRange(p.size, 0, 4096, "the service's image size (pixels)");
  RequireSetting(Setting::kDetail, p.detail);
  RequireRange(p.http.connect_timeout_s, 0.001, 86400, "the connection timeout (s)");
  RequireRange(p.http.total_timeout_s, 0.001, 86400, "the timeout (s)");
  RequireRange(double(p.http.max_response_bytes), 1, 1e12, "the largest answer (bytes)");
  RequireRange(p.http.max_retries, 0, 100, "the number of retries");
  RequireRange(p.http.backoff_s, 0, 3600, "the wait before a retry (s)");
  RequireRange(p.http.max_wait_s, 0, 86400, "the longest wait for a retry (s)");
  RequireRange(p.per_server, 1, 64, "the requests in flight per server");
  for (const auto& u : p.urls)
    if (u.empty()) throw vcg_ext::InvalidParameterError("a server of the pool has no URL");
}

std::vector<QImage> Inpaint(const QImage& image, const QImage& mask, const InpaintParams& p) {
  const std::string b = BackendName(p.backend);
  CheckInpaintParams(p);
  if (image.isNull() || mask.isNull() || image.size() != mask.size())
    throw InpaintError(b + ": the image and the mask must be images of the same size");
  if (p.pool && p.backend != Backend::kEmbedded) return p.pool->Inpaint(image, mask, p);
  std::vector<QImage> raw;
  switch (p.backend) {
  case Backend::kEmbedded:
    raw = InpaintEmbedded(image, mask, p);
    break;
  case Backend::kOpenAi:
    raw = OpenAi(image, mask, p);
    break;
  case Backend::kSdWebUi:
    raw = SdWebUi(image, mask, p);
    break;
  case Backend::kStability:
    raw = Stability(image, mask, p);
    break;
  case Backend::kComfyUi:
    raw = ComfyUi(image, mask, p);
    break;
  }
  // Back to the image's size, with the known pixels exactly as they were.
  const QImage original = image.convertToFormat(QImage::Format_RGB32);
  std::vector<QImage> out;
  for (size_t i = 0; i < raw.size(); ++i) {
    // The embedded inpainter's variations without detail are one picture, shared.
    if (i > 0 && raw[i].cacheKey() == raw[i - 1].cacheKey()) {
      out.push_back(out.back());
      continue;
    }
    QImage v =
        Scaled(raw[i].convertToFormat(QImage::Format_RGB32), original.width(), original.height());
    for (int y = 0; y < v.height(); ++y)
      for (int x = 0; x < v.width(); ++x)
        if (qGray(mask.pixel(x, y)) <= 127) v.setPixel(x, y, original.pixel(x, y));
    out.push_back(v);
  }
  return out;
}

} // namespace curvature_inpaint
