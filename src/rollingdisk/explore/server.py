"""The explorer's HTTP server: the page, its script and the JSON endpoints of :mod:`.api`.

Why the standard library's :class:`http.server.ThreadingHTTPServer` and a hand-written page:
the explorer must run offline, on a laptop or a cluster node without internet, from a
plain ``pip install rollingdisk``.  No web framework (Flask, FastAPI, ...) would earn a
place among the core dependencies for three JSON endpoints, and no CDN script (three.js,
plotly) may be fetched by the page: the map is a 2D canvas, the 3D view a 2D canvas with a
hand-written perspective projection, and everything the browser loads comes from this
server, out of ``rollingdisk/explore/static``.

Every request is answered: a bad query is HTTP 400 with ``{"error": "<one line>"}``, a bug
in rollingdisk is HTTP 500 with ``{"error": ...}`` (the traceback goes to the server's
log, never to the page), and the server goes on serving.  Under load: each connection is
served by a thread of a bounded pool (:data:`MAX_THREADS`; further connections wait in
the listen queue of :data:`LISTEN_BACKLOG`), a connection that sends nothing for
:data:`IDLE_TIMEOUT` seconds (a half-sent request) is closed, and a client that leaves
before its answer is written is no error (nothing in the log); the work per request is
bounded by :mod:`.api`.
"""

from __future__ import annotations

import ipaddress
import json
import mimetypes
import sys
import threading
import traceback
import webbrowser
from http import HTTPStatus
from http.server import BaseHTTPRequestHandler, ThreadingHTTPServer
from importlib import resources
from urllib.parse import parse_qs, urlsplit

from . import api

__all__ = ["ExplorerServer", "make_server", "explore", "LOOPBACK_HOSTS"]

#: Hosts that mean "this machine only".
LOOPBACK_HOSTS = ("127.0.0.1", "localhost", "::1")

#: The static files served, by URL path: the page, its script, and the view module that the
#: script loads (``view.js``, the notebook widget's module too).
STATIC = {"/": "index.html", "/index.html": "index.html", "/explore.js": "explore.js",
          "/view.js": "view.js", "/explore.css": "explore.css"}

ENDPOINTS = {"/api/map": api.map_payload, "/api/steady": api.steady_payload,
             "/api/simulate": api.simulate_payload}

#: Longest query string accepted (characters).
MAX_QUERY = 2000
#: Connections served at once (a thread each); more wait in the listen queue.
MAX_THREADS = 32
#: Connections the kernel queues before they are accepted (the listen backlog).
LISTEN_BACKLOG = 128
#: Seconds a connection may stay silent (a request half sent, an idle keep-alive).
IDLE_TIMEOUT = 10.0
#: What a client that left early raises in the writer: not an error of the server.
_CLIENT_GONE = (BrokenPipeError, ConnectionResetError, ConnectionAbortedError, TimeoutError)


def _static(name: str) -> bytes:
    return resources.files(__package__).joinpath("static", name).read_bytes()


class _Handler(BaseHTTPRequestHandler):
    server: ExplorerServer
    server_version = "rollingdisk-explore"
    protocol_version = "HTTP/1.1"
    timeout = IDLE_TIMEOUT  # on the socket: a silent client is let go

    def log_message(self, format, *args):  # noqa: A002 - BaseHTTPRequestHandler API
        if self.server.verbose:
            super().log_message(format, *args)

    def _send(self, status: int, body: bytes, content_type: str) -> None:
        self.send_response(status)
        self.send_header("Content-Type", content_type)
        self.send_header("Content-Length", str(len(body)))
        self.send_header("Cache-Control", "no-store")
        self.send_header("X-Content-Type-Options", "nosniff")
        self.end_headers()
        if self.command != "HEAD":
            self.wfile.write(body)

    def _json(self, status: int, payload: dict) -> None:
        body = json.dumps(payload, allow_nan=False, separators=(",", ":")).encode()
        self._send(status, body, "application/json")

    def do_HEAD(self):  # noqa: N802 - BaseHTTPRequestHandler API
        self.do_GET()

    def do_GET(self):  # noqa: N802 - BaseHTTPRequestHandler API
        parts = urlsplit(self.path)
        path = parts.path
        if path in STATIC:
            name = STATIC[path]
            ctype = mimetypes.guess_type(name)[0] or "application/octet-stream"
            if ctype.startswith("text/") or ctype.endswith("javascript"):
                ctype += "; charset=utf-8"
            self._send(HTTPStatus.OK, _static(name), ctype)
            return
        endpoint = ENDPOINTS.get(path)
        if endpoint is None:
            self._json(HTTPStatus.NOT_FOUND,
                       {"error": f"no such page {path[:80]!r}; the endpoints are "
                                 f"{', '.join(ENDPOINTS)}"})
            return
        if len(parts.query) > MAX_QUERY:
            self._json(HTTPStatus.BAD_REQUEST,
                       {"error": f"query too long ({len(parts.query)} characters, at most "
                                 f"{MAX_QUERY})"})
            return
        try:
            query = parse_qs(parts.query, keep_blank_values=True, strict_parsing=False,
                             max_num_fields=20)
            payload = endpoint(query, self.server.defaults)
        except api.ApiError as exc:
            self._json(HTTPStatus.BAD_REQUEST, {"error": str(exc)})
        except ValueError as exc:  # parse_qs: too many fields, bad encoding
            self._json(HTTPStatus.BAD_REQUEST, {"error": f"malformed query: {exc}"})
        except Exception as exc:  # a bug: logged with its traceback, the server serves on
            traceback.print_exc(file=sys.stderr)
            self._json(HTTPStatus.INTERNAL_SERVER_ERROR,
                       {"error": f"internal error in rollingdisk ({type(exc).__name__}); "
                                 "this is a bug, the server log has the traceback"})
        else:
            self._json(HTTPStatus.OK, payload)


class ExplorerServer(ThreadingHTTPServer):
    """A :class:`~http.server.ThreadingHTTPServer` serving the explorer.

    Attributes
    ----------
    defaults : dict
        ``{"h": ..., "ground": ..., "disk": ...}``: what the page starts with and what a
        query without ``h`` / ``ground`` means; ``disk`` the :class:`~rollingdisk.Disk` with
        a physical size it was started with (its steady motions come with SI values), or
        None.
    url : str
        ``http://host:port/`` with the port actually bound.
    """

    daemon_threads = True
    allow_reuse_address = True
    request_queue_size = LISTEN_BACKLOG

    def __init__(self, address, *, h: float, ground: str, verbose: bool = False,
                 disk=None):
        self.defaults = {"h": h, "ground": ground, "disk": disk}
        self.verbose = verbose
        self._slots = threading.BoundedSemaphore(MAX_THREADS)
        host = address[0]
        if ":" in host:
            import socket

            self.address_family = socket.AF_INET6
        super().__init__(address, _Handler)

    def process_request(self, request, client_address):
        """Serve the connection in a thread of the pool: wait for a free one (the next
        connections wait in the listen queue meanwhile)."""
        self._slots.acquire()
        try:
            super().process_request(request, client_address)
        except BaseException:
            self._slots.release()
            raise

    def process_request_thread(self, request, client_address):
        try:
            super().process_request_thread(request, client_address)
        finally:
            self._slots.release()

    def handle_error(self, request, client_address):
        """A client that left early (a broken pipe, a reset, its idle time out) is logged
        only when verbose, without a traceback; anything else is a bug: its traceback."""
        exc = sys.exc_info()[1]
        if isinstance(exc, _CLIENT_GONE):
            if self.verbose:
                print(f"rollingdisk explore: {client_address[0]} left "
                      f"({type(exc).__name__})", file=sys.stderr, flush=True)
            return
        super().handle_error(request, client_address)

    @property
    def url(self) -> str:
        host, port = self.server_address[:2]
        if ":" in host:
            host = f"[{host}]"
        return f"http://{host}:{port}/?h={self.defaults['h']!r}&ground={self.defaults['ground']}"

    def start_in_thread(self) -> threading.Thread:
        """Serve in a daemon thread (tests; stop with ``shutdown()`` then ``server_close()``)."""
        thread = threading.Thread(target=self.serve_forever, name="rollingdisk-explore",
                                  daemon=True)
        thread.start()
        return thread


def is_loopback(host: str) -> bool:
    """Whether ``host`` names this machine only (``localhost``, ``127.x.x.x``, ``::1``)."""
    if host.lower() == "localhost":
        return True
    try:
        return ipaddress.ip_address(host.strip("[]")).is_loopback
    except ValueError:
        return False


def _checked(h, ground, host, port) -> tuple[float, str, str, int]:
    import rollingdisk as rd
    from rollingdisk.model.disk import check_ground
    from rollingdisk.util.checks import check_int, check_real

    h = check_real("h", h, low=api.H_RANGE[0], high=api.H_RANGE[1])
    ground = check_ground(ground)
    if not isinstance(host, str) or not host:
        raise rd.ParameterTypeError(f"host must be a non-empty string, got {host!r}")
    port = check_int("port", port, low=0, high=65535)
    return h, ground, host, port


def make_server(h: float = 0.17, ground: str = "rough", host: str = "127.0.0.1",
                port: int = 0, *, verbose: bool = False, disk=None) -> ExplorerServer:
    """Bind the explorer's server (not yet serving).

    Parameters
    ----------
    h : float
        Half-thickness the page starts with, in [0, 100].
    ground : {"rough", "smooth"}
    host : str
        Address to bind; ``127.0.0.1`` (default) serves this machine only.
    port : int
        TCP port in [0, 65535]; 0 picks a free one (``server.url`` tells which).
    verbose : bool
        Log every request on stderr.
    disk : Disk, optional
        A disk with a physical size (``--disk euro-1``): the steady motions of its ``h``
        come with SI values beside the paper's.

    Returns
    -------
    ExplorerServer

    Raises
    ------
    ParameterError
        For ``h``, ``ground`` or ``port`` out of range.
    OSError
        If the address cannot be bound (port in use).
    """
    h, ground, host, port = _checked(h, ground, host, port)
    if disk is not None and getattr(disk, "radius", None) is None:
        disk = None  # no physical size: the paper's units only
    return ExplorerServer((host, port), h=h, ground=ground, verbose=verbose, disk=disk)


def explore(h: float = 0.17, ground: str = "rough", host: str = "127.0.0.1", port: int = 0,
            open_browser: bool = True, *, verbose: bool = False) -> None:
    """Serve the interactive explorer until Ctrl-C (which propagates, after a clean stop).

    Parameters
    ----------
    h : float
        Half-thickness the page starts with, in [0, 100] (the page can change it).
    ground : {"rough", "smooth"}
        The ground the page starts with.
    host : str
        Address to bind; the default ``127.0.0.1`` serves this machine only.
    port : int
        TCP port; 0 (default) picks a free one.
    open_browser : bool
        Open the page in the default web browser.
    verbose : bool
        Log every request on stderr.

    Examples
    --------
    >>> from rollingdisk.explore import explore
    >>> explore(h=0.17, ground="rough")          # doctest: +SKIP
    rollingdisk explore: serving http://127.0.0.1:43117/?h=0.17&ground=rough (Ctrl-C stops)
    """
    server = make_server(h, ground, host, port, verbose=verbose)
    if not is_loopback(host):
        print(f"rollingdisk explore: warning: binding {host}, beyond localhost: anyone who can "
              "reach this machine can use the explorer (there is no authentication)",
              file=sys.stderr, flush=True)
    try:
        print(f"rollingdisk explore: serving {server.url} (Ctrl-C stops)", flush=True)
        if open_browser:
            webbrowser.open(server.url)
        server.serve_forever()
    finally:
        server.server_close()
