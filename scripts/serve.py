#!/usr/bin/env python3
"""Serves a folder of the web edition on 127.0.0.1 with gzip, as any static host does: each page's WebAssembly, data
package and scripts are a few MiB that compress to about half. Python's http.server sends them as they are.
Usage: serve.py DIR PORT   (scripts/kit serve, tests/web/check_web.sh)"""
import email.utils
import gzip
import http.server
import io
import os
import sys
import threading

# What compresses: text, WebAssembly and Emscripten's data packages (shaders, JSON, raw floats). PNGs are compressed
# already.
COMPRESSED = {".html", ".js", ".css", ".md", ".json", ".wasm", ".data", ".svg", ".txt", ".glsl"}


class Handler(http.server.SimpleHTTPRequestHandler):
    cache = {}  # path -> (mtime, size, gzip bytes): each file compressed once while it is unchanged
    lock = threading.Lock()

    extensions_map = {**http.server.SimpleHTTPRequestHandler.extensions_map, ".wasm": "application/wasm",
                      ".md": "text/markdown; charset=utf-8", ".js": "text/javascript"}

    def log_message(self, format, *args):
        pass  # quiet: a page asks for dozens of files

    def send_head(self):
        path = self.translate_path(self.path)
        accepts = "gzip" in self.headers.get("Accept-Encoding", "")
        if not accepts or os.path.isdir(path) or os.path.splitext(path)[1] not in COMPRESSED or not os.path.isfile(path):
            return super().send_head()
        stat = os.stat(path)
        # A validator, so a browser keeps what it fetched (the shared data packages, each fetched by every page that reads
        # it) and asks again only whether it changed: a rebuilt site is seen at once, an unchanged file costs a 304.
        etag = '"%x-%x"' % (stat.st_mtime_ns, stat.st_size)
        since = self.headers.get("If-Modified-Since")
        try:
            unchanged_since = since is not None and email.utils.parsedate_to_datetime(since).timestamp() >= int(stat.st_mtime)
        except (TypeError, ValueError):
            unchanged_since = False
        if self.headers.get("If-None-Match") == etag or unchanged_since:
            self.send_response(304)
            self.send_header("ETag", etag)
            self.send_header("Cache-Control", "no-cache")
            self.end_headers()
            return None
        with self.lock:
            kept = self.cache.get(path)
            if not kept or kept[0] != stat.st_mtime_ns or kept[1] != stat.st_size:
                with open(path, "rb") as f:
                    kept = (stat.st_mtime_ns, stat.st_size, gzip.compress(f.read(), compresslevel=6))
                self.cache[path] = kept
        body = kept[2]
        self.send_response(200)
        self.send_header("Content-Type", self.guess_type(path))
        self.send_header("Content-Encoding", "gzip")
        self.send_header("Content-Length", str(len(body)))
        self.send_header("Vary", "Accept-Encoding")
        self.send_header("ETag", etag)
        self.send_header("Last-Modified", self.date_time_string(int(stat.st_mtime)))
        self.send_header("Cache-Control", "no-cache")
        self.end_headers()
        return io.BytesIO(body)


def main():
    if len(sys.argv) != 3 or not sys.argv[2].isdigit():
        print("usage: serve.py DIR PORT", file=sys.stderr)
        return 2
    folder, port = sys.argv[1], int(sys.argv[2])
    if not os.path.isdir(folder):
        print(f"serve: {folder} is not a folder", file=sys.stderr)
        return 2
    handler = lambda *args, **kwargs: Handler(*args, directory=folder, **kwargs)  # noqa: E731
    with http.server.ThreadingHTTPServer(("127.0.0.1", port), handler) as server:
        server.serve_forever()
    return 0


if __name__ == "__main__":
    sys.exit(main())
