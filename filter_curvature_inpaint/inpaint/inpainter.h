// Stage 8: complete a hole's curvature image into N variations (paper, sections 3.6-3.7).
//
// One entry point for every backend: the embedded one (offline, the default) and the remote
// services (OpenAI images/edits, Stable Diffusion web UIs, Stability AI, ComfyUI). Every
// backend works at a size its service accepts, returns the variations at the image's own size
// and pastes the known pixels back over them, so only the hole ever changes.
#pragma once

#include "http_client.h"

#include <QImage>

#include <cstdint>
#include <stdexcept>
#include <string>
#include <vector>

namespace curvature_inpaint {

class ServerPool;

/// Who completes the curvature images: the embedded inpainter (offline) or a remote service.
/// Named only where a person meets it (BackendName, ParseBackend).
enum class Backend { kEmbedded, kOpenAi, kSdWebUi, kStability, kComfyUi };

struct InpaintParams {
  Backend backend = Backend::kEmbedded;
  std::string url; ///< service address; empty: the backend's default
  /// Several servers of the backend (a pool; `url` is then ignored): FillHoles spreads the
  /// holes over them, at most `per_server` requests in flight on each.
  std::vector<std::string> urls;
  int per_server = 1;
  /// The pool a run shares (FillHoles makes it from `urls`); null: `url` alone. Not owned.
  ServerPool* pool = nullptr;
  std::string model;  ///< openai: dall-e-2 (default) or gpt-image-1
  std::string prompt; ///< empty: the paper's prompt for the backend
  std::string negative_prompt;
  int variations = 4;
  uint32_t seed = 1;
  int size = 0;        ///< service-side image size; 0: the backend's default
  double detail = 1.0; ///< embedded: amplitude of the synthesised detail
  /// embedded: the detail's scale, pixels (the spacing of the patch's vertices in the image,
  /// which the pipeline knows per hole); 0: 1/64 of the image's side
  double detail_scale = 0;
  std::string workflow_file; ///< comfyui: an edited workflow; empty: the shipped one
  HttpOptions http;
};

/// Why a backend produced no variations: one sentence naming the backend, and for a service
/// its HTTP status and its own message. Never contains an API key.
class InpaintError : public std::runtime_error {
public:
  explicit InpaintError(const std::string& what) : std::runtime_error(what) {}
};

/// Throws vcg_ext::InvalidParameterError naming the first parameter out of its range.
void CheckInpaintParams(const InpaintParams& params);

/// The backends this build knows, in the order the filter's list and the dialog show them.
const std::vector<Backend>& InpaintBackends();

/// The backend at `index` of InpaintBackends(), the nearest end where it is out of range (a
/// list's position: the filter's enum, the dialog's list).
Backend BackendAt(int index);

/// The backend's name on the command line, in scripts, settings and reports ("embedded",
/// "openai", "sd-webui", "stability", "comfyui").
std::string BackendName(Backend backend);

/// The backend of that name. Throws vcg_ext::InvalidParameterError naming the known ones.
Backend ParseBackend(const std::string& name);

/// What a front end needs to know of a backend to set it up.
struct BackendInfo {
  std::string default_url;      ///< where it is reached when no URL is given; empty: nowhere
  std::string key_variable;     ///< environment variable with its credentials; empty: none
  bool key_required = false;    ///< whether the service refuses without them
  std::string default_model;    ///< empty: the service has no model choice
  bool remote = true;           ///< reached over HTTP: it takes a URL and a prompt
  bool negative_prompt = false; ///< it takes what the image should not show
};

/// The backend's defaults.
const BackendInfo& DescribeBackend(Backend backend);

/// The prompt the backend gets when none is given (the paper's, where it gives one).
std::string DefaultPrompt(Backend backend);

/// Completes the hole of `image` (white pixels of `mask`, same size) into params.variations
/// images of the same size. Throws InpaintError, or vcg_ext::CancelledError when
/// params.http.cancelled asks to stop.
std::vector<QImage> Inpaint(const QImage& image, const QImage& mask, const InpaintParams& params);

/// The embedded backend alone: biharmonic continuation of the curvature field plus detail
/// synthesised from the known region (embedded_inpainter.cpp).
std::vector<QImage> InpaintEmbedded(const QImage& image, const QImage& mask,
                                    const InpaintParams& params);

/// The embedded backend's first variation at each detail amplitude (params.detail ignored),
/// from one continuation: what the fake-hole validation compares. Same size as `image`.
std::vector<QImage> InpaintEmbeddedAmplitudes(const QImage& image, const QImage& mask,
                                              const InpaintParams& params,
                                              const std::vector<double>& amplitudes);

/// `count` completions by the exemplar inpainter (vcg_ext/exemplar_inpainting.h: patches of
/// the known region copied in from the border inwards, structures first), one per seed from
/// params.seed, on a grid of a few pixels per params.detail_scale. Fewer (none) where the
/// image has no fully known patch.
std::vector<QImage> InpaintExemplarVariations(const QImage& image, const QImage& mask,
                                              const InpaintParams& params, int count);

} // namespace curvature_inpaint
