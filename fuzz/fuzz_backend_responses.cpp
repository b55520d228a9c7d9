// libFuzzer target: the remote backends' handling of what a service answers (status, JSON,
// base64, PNG decoding, sizes, ComfyUI's multi-step exchange), with the network replaced by
// the fuzzer's bytes. Input: a backend selector, a status selector, then the bodies of the
// successive answers, separated by lines "----" (the last one repeats).
#include "fuzz_input.h"
#include "inpaint/inpainter.h"

#include <cstdint>
#include <cstdlib>
#include <string>
#include <vector>

using namespace curvature_inpaint;

extern "C" int LLVMFuzzerInitialize(int* argc, char*** argv) {
  setenv("OPENAI_API_KEY", "sk-fuzz-0000000000", 1);
  setenv("STABILITY_API_KEY", "sk-fuzz-0000000000", 1);
  fuzz::StartQt(argc, argv);
  return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  if (size < 2) return 0;
  static const Backend kBackends[] = {Backend::kOpenAi, Backend::kSdWebUi, Backend::kStability,
                                      Backend::kComfyUi};
  static const long kStatuses[] = {200, 200, 200, 200, 201, 302, 400, 401, 404, 429, 500, 503};
  // The answers, in order, separated by "\n----\n".
  const std::string rest(reinterpret_cast<const char*>(data) + 2, size - 2), sep = "\n----\n";
  std::vector<std::string> bodies;
  for (size_t at = 0;;) {
    const size_t end = rest.find(sep, at);
    bodies.push_back(rest.substr(at, end == std::string::npos ? std::string::npos : end - at));
    if (end == std::string::npos) break;
    at = end + sep.size();
  }
  InpaintParams p;
  p.backend = kBackends[data[0] % 4];
  p.url = "http://fuzz.invalid";
  p.variations = 1 + data[1] % 3;
  p.http.max_retries = 0;
  p.http.total_timeout_s = 0.05; // ComfyUI's polling gives up quickly
  const long status = kStatuses[(data[1] >> 2) % 12];
  size_t next = 0;
  p.http.transport = [&](const HttpRequest&) {
    HttpResponse r;
    r.status = status;
    r.body = bodies[std::min(next++, bodies.size() - 1)];
    return r;
  };
  QImage image(64, 64, QImage::Format_RGB32), mask(64, 64, QImage::Format_Grayscale8);
  image.fill(qRgb(0, 200, 60));
  mask.fill(0);
  for (int y = 16; y < 48; ++y)
    for (int x = 16; x < 48; ++x) mask.setPixel(x, y, 255);
  try {
    const std::vector<QImage> out = Inpaint(image, mask, p);
    for (const QImage& v : out)
      if (v.size() != image.size()) abort(); // every variation comes back at the image's size
  } catch (const InpaintError&) {
  }
  return 0;
}
