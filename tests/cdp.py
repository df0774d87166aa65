"""One headless Chromium for many page loads, driven over the DevTools protocol on a pipe (``--remote-debugging-pipe``:
commands on the browser's fd 3, answers and events on its fd 4, each a JSON message ended by a NUL byte).

Starting Chromium costs about three CPU-seconds, as much as loading and typesetting most chapters: the browser
check loads every page twice (a 1400 px window and a phone's 390 px), so it starts one browser and loads every page
in it. Nothing but the standard library: no browser is downloaded and no client package is needed.
"""
from __future__ import annotations

import base64
import contextlib
import fcntl
import json
import os
import select
import subprocess
import tempfile
import time


class BrowserError(RuntimeError):
    """The browser answered a command with an error, or gave no answer in time."""


class Browser:
    """A headless Chromium and one tab in it (:meth:`load` pages into it one after another).

    Parameters
    ----------
    binary : str
        The Chromium to run.
    flags : list of str
        Its command-line flags (headless, offline, no sandbox...).
    """

    def __init__(self, binary: str, flags: list[str]):
        self._profile = tempfile.TemporaryDirectory()
        to_browser, self._out = os.pipe()
        self._in, from_browser = os.pipe()
        # the child's ends above fd 4 first (either could itself be 3 or 4), then moved to 3 and 4 by the bash that
        # execs Chromium (no preexec_fn: the test workers have threads; dash takes one-digit fds only)
        ends = [fcntl.fcntl(fd, fcntl.F_DUPFD_CLOEXEC, 5) for fd in (to_browser, from_browser)]
        os.close(to_browser)
        os.close(from_browser)
        r, w = ends
        self.proc, self.session, self._buffer, self._next, self.events = None, None, b"", 0, []
        try:
            self.proc = subprocess.Popen(
                ["/bin/bash", "-c", f'exec "$@" 3<&{r} 4>&{w} {r}<&- {w}>&-', "bash", binary, *flags,
                 "--remote-debugging-pipe", f"--user-data-dir={self._profile.name}"],
                stdin=subprocess.DEVNULL, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL, pass_fds=ends)
            while ends:  # the child has its own copies now
                os.close(ends.pop())
            self.send("Browser.getVersion", timeout=30)  # it answers: it has started
        except BaseException:  # a browser that did not start is not left running
            while ends:
                os.close(ends.pop())
            self.close()
            raise

    def _new_tab(self) -> None:
        """A fresh tab for the next page (the last one closed): nothing of one page, its events or its virtual
        time, carries over to the next."""
        if self.session is not None:
            old, self.session = self.session, None
            self.send("Target.closeTarget", targetId=self._target)
            self.events = [e for e in self.events if e.get("sessionId") != old]
        self._target = self.send("Target.createTarget", url="about:blank")["targetId"]
        self.session = self.send("Target.attachToTarget", targetId=self._target, flatten=True)["sessionId"]
        for domain in ("Page", "Runtime", "Log"):
            self.send(f"{domain}.enable", session=self.session)

    def _read(self, deadline: float) -> dict:
        while b"\0" not in self._buffer:
            left = deadline - time.monotonic()
            if left <= 0 or not select.select([self._in], [], [], left)[0]:
                raise BrowserError("Chromium gave no answer in time")
            chunk = os.read(self._in, 1 << 20)
            if not chunk:
                raise BrowserError("Chromium closed its pipe")
            self._buffer += chunk
        message, self._buffer = self._buffer.split(b"\0", 1)
        return json.loads(message)

    def send(self, method: str, session: str | None = None, timeout: float = 120, **params) -> dict:
        """Send one command and wait for its answer; the events that arrive meanwhile go to :attr:`events`.

        Parameters
        ----------
        method : str
            The protocol's method, e.g. ``Page.navigate``.
        session : str or None
            The tab's session (None: the browser itself).
        timeout : float
            Seconds to wait for the answer.
        **params
            The method's parameters.

        Returns
        -------
        dict
            The answer's result.
        """
        self._next += 1
        message = {"id": self._next, "method": method, "params": params, **({"sessionId": session} if session else {})}
        os.write(self._out, json.dumps(message).encode() + b"\0")
        deadline = time.monotonic() + timeout
        while True:
            answer = self._read(deadline)
            if answer.get("id") == self._next:
                if "error" in answer:
                    raise BrowserError(f"{method}: {answer['error']}")
                return answer["result"]
            self.events.append(answer)

    def wait_for(self, method: str, timeout: float = 120) -> dict:
        """The first event ``method`` of the tab not yet taken (waiting for it if none has arrived).

        Parameters
        ----------
        method : str
            The event, e.g. ``Page.loadEventFired``.
        timeout : float
            Seconds to wait.

        Returns
        -------
        dict
            The event's parameters.
        """
        deadline = time.monotonic() + timeout
        while True:
            for i, event in enumerate(self.events):
                if event.get("method") == method and event.get("sessionId") == self.session:
                    return self.events.pop(i)["params"]
            self.events.append(self._read(deadline))

    def evaluate(self, expression: str, timeout: float = 120):
        """The value of a JavaScript expression in the tab (a promise is awaited).

        Parameters
        ----------
        expression : str
            The expression.
        timeout : float
            Seconds to wait for it.

        Returns
        -------
        object
            Its value, as JSON gives it.
        """
        out = self.send("Runtime.evaluate", session=self.session, timeout=timeout, expression=expression,
                        awaitPromise=True, returnByValue=True)
        if "exceptionDetails" in out:
            raise BrowserError(f"{expression[:60]}: {out['exceptionDetails'].get('text')}")
        return out["result"].get("value")

    def load(self, url: str, width: int, height: int = 1000, ready: str = "true", timeout: float = 120,
             settle_ms: int = 20_000):
        """Load ``url`` in a new tab ``width`` px wide, wait until the expression ``ready`` is true, then let the
        page run ``settle_ms`` more of virtual time (its pending timers fire at once, as ``--virtual-time-budget``
        lets them: a script that fails a few seconds after the load is still heard); returns the console's
        messages of this load (:meth:`dom` gives the page as it then stands).

        Parameters
        ----------
        url : str
            The page.
        width, height : int
            The window (the page's media queries see these), px.
        ready : str
            A JavaScript expression (or promise) true once the page is complete, tried every 100 ms.
        timeout : float
            Seconds for the page to load and become ready.
        settle_ms : int
            Virtual milliseconds the page runs on after it is ready, before its console is read.

        Returns
        -------
        list of tuple
            Each console message, failed resource and uncaught exception of the load, as (level, text).
        """
        self._new_tab()
        self.send("Emulation.setDeviceMetricsOverride", session=self.session, width=width, height=height,
                  deviceScaleFactor=1, mobile=False)
        self.send("Page.navigate", session=self.session, url=url)
        self.wait_for("Page.loadEventFired", timeout)
        poll = (f"new Promise(ok => {{ const t0 = Date.now(); const go = () => Promise.resolve().then(() => ({ready}))"
                f".then(r => r ? ok(true) : Date.now() - t0 > {timeout * 1000} ? ok(false) : setTimeout(go, 100), "
                f"() => setTimeout(go, 100)); go(); }})")
        if not self.evaluate(poll, timeout + 10):
            raise BrowserError(f"{url}: not ready after {timeout} s ({ready})")
        if settle_ms:
            self.send("Emulation.setVirtualTimePolicy", session=self.session, policy="advance", budget=settle_ms)
            self.wait_for("Emulation.virtualTimeBudgetExpired", timeout)
        return self.console()

    def dom(self) -> str:
        """The tab's page as it stands (its DOM serialised, as ``--dump-dom`` writes it).

        Returns
        -------
        str
            The HTML.
        """
        return self.evaluate("document.documentElement.outerHTML")

    def console(self) -> list[tuple[str, str]]:
        """The console's messages, the resources that failed and the uncaught exceptions of the tab since the last
        load.

        Returns
        -------
        list of tuple
            (level, text) per message.
        """
        lines = []
        for event in self.events:
            if event.get("sessionId") != self.session:
                continue
            p = event.get("params", {})
            if event.get("method") == "Runtime.consoleAPICalled":
                lines.append((p["type"], " ".join(str(a.get("value", a.get("description", ""))) for a in p["args"])))
            elif event.get("method") == "Runtime.exceptionThrown":
                d = p["exceptionDetails"]
                lines.append(("error", f"{d.get('text', '')} {d.get('exception', {}).get('description', '')}".strip()))
            elif event.get("method") == "Log.entryAdded":
                lines.append((p["entry"]["level"], f"{p['entry']['text']} {p['entry'].get('url', '')}".strip()))
        return lines

    def screenshot(self) -> bytes:
        """The tab's window as it stands, a PNG.

        Returns
        -------
        bytes
            The image.
        """
        return base64.b64decode(self.send("Page.captureScreenshot", session=self.session, format="png")["data"])

    def close(self) -> None:
        """Close the browser (and its pipes and profile)."""
        if self.proc is not None:
            try:
                self.send("Browser.close", timeout=10)
            except (BrowserError, OSError, AttributeError):
                pass
            try:
                self.proc.wait(timeout=10)
            except subprocess.TimeoutExpired:
                self.proc.kill()
                self.proc.wait()
            self.proc = None
        for fd in (self._in, self._out):
            with contextlib.suppress(OSError):
                os.close(fd)
        self._profile.cleanup()

    def __enter__(self):
        return self

    def __exit__(self, *exc):
        self.close()
