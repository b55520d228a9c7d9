"""A local stand-in for each inpainting service, on 127.0.0.1, that checks every request as
strictly as the real one (method, path, headers, multipart fields and types, mask semantics,
PNG validity and size) and answers like it, errors included.

The first path segment picks the scenario: /ok/..., /unauthorized/..., /rate-limited/...
(one 429 with retry-after, then success), /server-error/..., /slow/... (answers after
SLOW_SECONDS), /garbage/..., /wrong-size/..., /oversized/..., /bomb/... (a PNG declaring
100000 x 100000 pixels). A request that breaks the protocol gets 400 with the reason, so a
test expecting success fails on it.
"""
import base64
import email.parser
import email.policy
import json
import threading
import time
import uuid
from http.server import BaseHTTPRequestHandler, ThreadingHTTPServer
from urllib.parse import parse_qs, urlparse

import pngs

OPENAI_KEY = "sk-test-0123456789abcdefSECRET"
STABILITY_KEY = "sk-stab-0123456789abcdefSECRET"
SD_AUTH = "alice:wonderland"
SLOW_SECONDS = 4
OVERSIZED_BYTES = 3 << 20


class ProtocolError(Exception):
    pass


def require(cond, why):
    if not cond:
        raise ProtocolError(why)


def multipart(headers, body):
    ctype = headers.get("Content-Type", "")
    require(ctype.startswith("multipart/form-data; boundary="), f"Content-Type is {ctype!r}, not multipart/form-data")
    msg = email.parser.BytesParser(policy=email.policy.HTTP).parsebytes(
        b"Content-Type: " + ctype.encode() + b"\r\n\r\n" + body)
    fields, files = {}, {}
    for part in msg.iter_parts():
        name = part.get_param("name", header="content-disposition")
        filename = part.get_param("filename", header="content-disposition")
        data = part.get_payload(decode=True)
        if filename:
            files[name] = (filename, part.get_content_type(), data)
        else:
            fields[name] = data.decode()
    return fields, files


def png_of(data, what):
    try:
        return pngs.decode(data)
    except (pngs.PngError, Exception) as e:  # noqa: B014 - zlib errors too
        raise ProtocolError(f"{what} is not a valid PNG: {e}")


def check_bw_mask(png, what, opaque=True):
    w, h, ch, rows = png
    require(not opaque or ch in (1, 3), f"{what} must be opaque (no alpha), has {ch} channels")
    values = set()
    for row in rows:
        values.update(row[0::ch] if ch in (1, 2) else row[0::ch])
    require(values <= {0, 255}, f"{what} must be black and white only")
    require(255 in values and 0 in values, f"{what} must have both a white hole and black known pixels")


class Handler(BaseHTTPRequestHandler):
    server_version = "inpaint-test/1"

    def log_message(self, *args):
        pass

    # --- plumbing -------------------------------------------------------------------------
    def body(self):
        return self._body

    def send(self, status, payload, content_type="application/json", headers=()):
        data = payload if isinstance(payload, bytes) else json.dumps(payload).encode()
        self.send_response(status)
        self.send_header("Content-Type", content_type)
        self.send_header("Content-Length", str(len(data)))
        for k, v in headers:
            self.send_header(k, v)
        self.end_headers()
        try:
            self.wfile.write(data)
        except (BrokenPipeError, ConnectionResetError):
            pass

    def route(self, method):
        # Read the whole request first, as a real server does before it answers.
        self._body = self.rfile.read(int(self.headers.get("Content-Length", "0")))
        url = urlparse(self.path)
        parts = url.path.split("/", 2)
        scenario, rest = parts[1], "/" + (parts[2] if len(parts) > 2 else "")
        self.server.requests.append((scenario, method, rest))
        service = self.service_of(rest)
        if scenario == "slow":
            time.sleep(SLOW_SECONDS)
        if scenario == "rate-limited":
            key = (service, rest)
            if key not in self.server.limited:
                self.server.limited.add(key)
                return self.send(429, self.error_body(service, 429, "Rate limit reached, slow down"),
                                 headers=[("retry-after", "1")])
        if scenario == "server-error":
            return self.send(500, self.error_body(service, 500, "The server had an error processing your request"))
        if scenario == "oversized":
            return self.send(200, b"{" + b" " * OVERSIZED_BYTES + b"}")
        if scenario == "garbage":
            return self.send(200, b"<html>upstream connect error or disconnect/reset</html>", "text/html")
        if scenario == "drip":
            return self.drip()
        if scenario == "endless":
            return self.endless()
        if scenario == "redirect":
            return self.send(302, b"", "text/plain", headers=[("Location", "http://example.invalid/collect")])
        if scenario == "deep-json":
            return self.send(200, b"[" * 100000 + b"]" * 100000)
        if scenario == "bad-base64" and service != "comfyui":
            junk = "@@not*base64@@"
            return self.send(200, {"openai": {"created": 1, "data": [{"b64_json": junk}]},
                                   "sd-webui": {"images": [junk], "parameters": {}, "info": "{}"},
                                   "stability": {"image": junk, "finish_reason": "SUCCESS", "seed": 1}}[service])
        try:
            handler = getattr(self, "do_" + service.replace("-", "_"))
            handler(method, rest, url, scenario)
        except ProtocolError as e:
            self.server.violations.append(str(e))
            self.send(400, {"error": {"message": f"test server: {e}", "type": "invalid_request_error"}})

    def do_GET(self):
        self.route("GET")

    def do_POST(self):
        self.route("POST")

    @staticmethod
    def service_of(path):
        if path.startswith("/v1/images"):
            return "openai"
        if path.startswith("/sdapi"):
            return "sd-webui"
        if path.startswith("/v2beta"):
            return "stability"
        return "comfyui"

    @staticmethod
    def error_body(service, status, message):
        if service == "openai":
            return {"error": {"message": message, "type": "server_error", "param": None, "code": None}}
        if service == "sd-webui":
            return {"error": "HTTPException", "detail": message, "body": "", "errors": ""}
        if service == "stability":
            return {"id": "0" * 32, "name": "server_error", "errors": [message]}
        return {"error": {"type": "server_error", "message": message, "details": "", "extra_info": {}}}

    def drip(self):
        """A valid start, then one byte every 0.3 s: only a total timeout ends it."""
        self.send_response(200)
        self.send_header("Content-Type", "application/json")
        self.send_header("Content-Length", "100000")
        self.end_headers()
        try:
            self.wfile.write(b"{")
            for _ in range(100):
                time.sleep(0.3)
                self.wfile.write(b" ")
                self.wfile.flush()
        except (BrokenPipeError, ConnectionResetError):
            pass

    def endless(self):
        """A body with no length that never ends (until the client hangs up)."""
        self.send_response(200)
        self.send_header("Content-Type", "application/json")
        self.end_headers()
        try:
            self.wfile.write(b"{\"data\": \"")
            for _ in range(2000):  # 128 MB at most
                self.wfile.write(b"A" * 65536)
        except (BrokenPipeError, ConnectionResetError):
            pass

    def result_png(self, scenario, w, h):
        if scenario == "not-image":
            return b"<html><body>Service Unavailable</body></html>"
        if scenario == "wrong-size":
            return pngs.encode(w // 2, h // 2)
        if scenario == "bomb":
            return pngs.bomb()
        return pngs.encode(w, h)

    # --- OpenAI images/edits --------------------------------------------------------------
    def do_openai(self, method, rest, url, scenario):
        require(method == "POST" and rest == "/v1/images/edits", f"unexpected {method} {rest}")
        auth = self.headers.get("Authorization", "")
        fields, files = multipart(self.headers, self.body())
        if auth != "Bearer " + OPENAI_KEY or scenario == "unauthorized":
            shown = auth.replace("Bearer ", "")
            return self.send(401, {"error": {"message": f"Incorrect API key provided: {shown}. You can find "
                                             "your API key at https://platform.openai.com/account/api-keys.",
                                             "type": "invalid_request_error", "param": None,
                                             "code": "invalid_api_key"}})
        require(set(files) >= {"image"}, f"missing the image file; files: {sorted(files)}")
        model = fields.get("model")
        require(model in ("dall-e-2", "gpt-image-1"), f"model {model!r}")
        name, ctype, data = files["image"]
        require(ctype == "image/png", f"image part has type {ctype}")
        w, h, ch, rows = png_of(data, "image")
        require(w == h, "image must be square")
        require(len(data) < 4 << 20, "image must be under 4 MB")
        size = fields.get("size")
        if model == "dall-e-2":
            require(w in (256, 512, 1024), f"dall-e-2 image size {w}")
            require(fields.get("response_format") == "b64_json", "response_format must be b64_json")
        else:
            require(w == 1024, f"gpt-image-1 image size {w}")
            require("response_format" not in fields, "gpt-image-1 takes no response_format")
        require(size == f"{w}x{h}", f"size {size!r} for a {w}x{h} image")
        require(ch == 4, "the image must be RGBA with the hole transparent")
        alphas = {row[i] for row in rows for i in range(3, len(row), 4)}
        require(0 in alphas and 255 in alphas, "the image must have a transparent hole and opaque known pixels")
        if "mask" in files:
            mw, mh, mch, _ = png_of(files["mask"][2], "mask")
            require((mw, mh) == (w, h) and mch == 4, "mask must be an RGBA PNG of the image's size")
        prompt = fields.get("prompt", "")
        require(0 < len(prompt) <= 1000, "prompt must be 1 to 1000 characters")
        n = int(fields.get("n", "1"))
        require(1 <= n <= 10, f"n = {n}")
        b64 = base64.b64encode(self.result_png(scenario, w, h)).decode()
        self.send(200, {"created": int(time.time()), "data": [{"b64_json": b64} for _ in range(n)]})

    # --- AUTOMATIC1111 / Forge / SD.Next --------------------------------------------------
    def do_sd_webui(self, method, rest, url, scenario):
        require(method == "POST" and rest == "/sdapi/v1/img2img", f"unexpected {method} {rest}")
        auth = self.headers.get("Authorization", "")
        expected = "Basic " + base64.b64encode(SD_AUTH.encode()).decode()
        if auth != expected or scenario == "unauthorized":
            return self.send(401, {"detail": "Not authenticated"})
        require(self.headers.get("Content-Type", "").startswith("application/json"), "body must be JSON")
        try:
            req = json.loads(self.body())
        except ValueError:
            raise ProtocolError("body is not valid JSON")
        problems = [{"loc": ["body", k], "msg": "field required", "type": "value_error.missing"}
                    for k in ("init_images", "mask", "prompt", "width", "height", "batch_size")
                    if k not in req]
        if problems:
            return self.send(422, {"detail": problems})
        w, h = req["width"], req["height"]
        require(w % 8 == 0 and h % 8 == 0, f"width and height must be multiples of 8, got {w}x{h}")
        iw, ih, _, _ = png_of(base64.b64decode(req["init_images"][0]), "init image")
        require((iw, ih) == (w, h), f"init image {iw}x{ih} for width/height {w}x{h}")
        mask = png_of(base64.b64decode(req["mask"]), "mask")
        require(mask[:2] == (w, h), "mask size differs from the image")
        check_bw_mask(mask, "mask")
        require(req.get("inpainting_mask_invert", 0) == 0, "the mask must be white = repaint")
        require(isinstance(req.get("seed"), (int, float)), "seed must be a number")
        n = req["batch_size"] * req.get("n_iter", 1)
        b64 = base64.b64encode(self.result_png(scenario, w, h)).decode()
        self.send(200, {"images": [b64] * n, "parameters": req, "info": json.dumps({"seed": req["seed"]})})

    # --- Stability AI ---------------------------------------------------------------------
    def do_stability(self, method, rest, url, scenario):
        require(method == "POST" and rest == "/v2beta/stable-image/edit/inpaint", f"unexpected {method} {rest}")
        if self.headers.get("authorization") != "Bearer " + STABILITY_KEY or scenario == "unauthorized":
            return self.send(401, {"id": "1" * 32, "name": "unauthorized", "errors": ["authentication failed"]})
        require(self.headers.get("accept") == "application/json", "accept must be application/json")
        fields, files = multipart(self.headers, self.body())
        require(set(files) >= {"image", "mask"}, f"files {sorted(files)}")
        image = png_of(files["image"][2], "image")
        mask = png_of(files["mask"][2], "mask")
        require(mask[:2] == image[:2], "mask size differs from the image")
        check_bw_mask(mask, "mask")
        if not fields.get("prompt"):
            return self.send(400, {"id": "2" * 32, "name": "bad_request", "errors": ["prompt: is required"]})
        require(fields.get("output_format") == "png", "output_format must be png")
        seed = int(fields.get("seed", "0"))
        b64 = base64.b64encode(self.result_png(scenario, image[0], image[1])).decode()
        self.send(200, {"image": b64, "finish_reason": "SUCCESS", "seed": seed})

    # --- ComfyUI --------------------------------------------------------------------------
    def do_comfyui(self, method, rest, url, scenario):
        state = self.server.comfy
        if method == "POST" and rest == "/upload/image":
            fields, files = multipart(self.headers, self.body())
            require("image" in files, "upload without an image file")
            name, ctype, data = files["image"]
            png = png_of(data, "uploaded image")
            state["uploads"][name] = png
            return self.send(200, {"name": name, "subfolder": "", "type": fields.get("type", "input")})
        if method == "POST" and rest == "/prompt":
            try:
                req = json.loads(self.body())
            except ValueError:
                raise ProtocolError("body is not valid JSON")
            graph = req.get("prompt")
            require(isinstance(graph, dict), "prompt must be a node graph")
            kinds = {n.get("class_type"): n for n in graph.values()}
            for k in ("LoadImage", "LoadImageMask", "VAEEncodeForInpaint", "KSampler", "VAEDecode", "SaveImage"):
                require(k in kinds, f"workflow lacks {k}")
            image = kinds["LoadImage"]["inputs"]["image"]
            mask = kinds["LoadImageMask"]["inputs"]["image"]
            require(image in state["uploads"] and mask in state["uploads"], "workflow names files never uploaded")
            check_bw_mask(state["uploads"][mask], "mask")
            require(isinstance(kinds["KSampler"]["inputs"]["seed"], int), "KSampler seed must be an integer")
            w, h = state["uploads"][image][:2]
            pid = str(uuid.uuid4())
            state["prompts"][pid] = {"polls": 0, "size": (w, h), "scenario": scenario}
            return self.send(200, {"prompt_id": pid, "number": len(state["prompts"]), "node_errors": {}})
        if method == "GET" and rest.startswith("/history/"):
            pid = rest[len("/history/"):]
            p = state["prompts"].get(pid)
            if p is None:
                return self.send(200, {})
            p["polls"] += 1
            if p["polls"] < 2:  # still running
                return self.send(200, {})
            fname = f"ci_{pid[:8]}_00001_.png"
            state["outputs"][fname] = p
            return self.send(200, {pid: {"outputs": {"9": {"images": [
                {"filename": fname, "subfolder": "", "type": "output"}]}},
                "status": {"status_str": "success", "completed": True}}})
        if method == "GET" and rest == "/view":
            q = parse_qs(url.query, keep_blank_values=True)
            require(q.get("type") == ["output"], "view must ask for type=output")
            p = state["outputs"].get(q.get("filename", [""])[0])
            require(p is not None, "view of an unknown file")
            return self.send(200, self.result_png(p["scenario"], *p["size"]), "image/png")
        raise ProtocolError(f"unexpected {method} {rest}")


class Server:
    """Starts the stand-in services on an ephemeral port in a background thread."""

    def __init__(self):
        self.httpd = ThreadingHTTPServer(("127.0.0.1", 0), Handler)
        self.httpd.daemon_threads = True
        self.httpd.requests, self.httpd.violations, self.httpd.limited = [], [], set()
        self.httpd.comfy = {"uploads": {}, "prompts": {}, "outputs": {}}
        self.thread = threading.Thread(target=self.httpd.serve_forever, daemon=True)
        self.thread.start()

    def url(self, scenario):
        return f"http://127.0.0.1:{self.httpd.server_address[1]}/{scenario}"

    @property
    def violations(self):
        return self.httpd.violations

    def stop(self):
        self.httpd.shutdown()
        self.httpd.server_close()
