#!/usr/bin/env python3
"""remote_page.py VITRINE OUTDIR: the control page, loaded in headless Chromium through chromedriver's
W3C WebDriver protocol (standard library only), drives a headless neon run over its WebSocket: arrow
keys on the `particles` slider change the parameter, a preset saved from the page is offered back as
the user's and one the gallery lacks is refused on the page, and a drag on the touch pad releases tubes
along its path. Requests without the access token are refused. Afterwards no Chromium of the test's is
left running (the WebDriver session is ended, which closes the browser, before chromedriver stops)."""
import json, os, re, shutil, signal, socket, struct, subprocess, sys, time, urllib.error, urllib.request

vitrine, out = sys.argv[1], sys.argv[2]
os.makedirs(out, exist_ok=True)
events = os.path.join(out, "remote_events.jsonl")
if os.path.exists(events):
    os.remove(events)


def fail(message):
    print("FAIL:", message)
    sys.exit(1)


def free_port():
    with socket.socket() as s:
        s.bind(("127.0.0.1", 0))
        return s.getsockname()[1]


def http(method, url, body=None, timeout=30):
    data = json.dumps(body).encode() if body is not None else None
    request = urllib.request.Request(url, data=data, method=method, headers={"Content-Type": "application/json"})
    try:
        with urllib.request.urlopen(request, timeout=timeout) as response:
            return json.loads(response.read() or b"null")
    except urllib.error.HTTPError as e:
        fail(f"WebDriver {method} {url}: {e.code} {e.read()[:400]!r}")


def status_of(url):
    try:
        with urllib.request.urlopen(url, timeout=10) as response:
            return response.status
    except urllib.error.HTTPError as e:
        return e.code


run = subprocess.Popen([vitrine, "--headless", "--scene", "neon", "--size", "64x36", "--frames", "3600",
                        "--set", "chains=256", "--set", "particles=32", "--set", "autopilot_idle=60",
                        "--validate", "--remote",
                        "--map", "osc.fader=bloom_strength:0:2",
                        "--remote-bind", "127.0.0.1:0", "--events", events, "--out", os.path.join(out, "remote.exr")],
                       stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True,
                       env=dict(os.environ, XDG_CONFIG_HOME=os.path.join(out, "config")))  # its presets: not the user's
profile = os.path.join(out, "chromium-profile")  # names the test's browser processes on their command line
shutil.rmtree(profile, ignore_errors=True)  # a fresh profile each run


def browsers_left():
    found = []
    for pid in filter(str.isdigit, os.listdir("/proc")):
        try:
            with open(f"/proc/{pid}/cmdline", "rb") as f:
                if profile.encode() in f.read():
                    found.append(int(pid))
        except OSError:
            pass
    return found


driver = session = None
try:
    url = None
    deadline = time.time() + 60
    while time.time() < deadline and url is None:
        line = run.stdout.readline()
        if not line:
            fail("vitrine ended before printing the page's address")
        match = re.search(r"(http://\S+\?token=([0-9a-f]+))", line)
        if match:
            url, token = match.group(1), match.group(2)
    if url is None:
        fail("no page address within 60 s")
    base = url.split("?")[0]
    # The token guards the page and its catalogue. Without it, / is at most OSCQuery's namespace (JSON,
    # for native clients at addresses OSC trusts), never the page, and nothing to a browser's request.
    assert status_of(base + "index.html") == 403, "a request without the token must be refused"
    assert status_of(base + "index.html?token=" + "0" * len(token)) == 403, "a wrong token must be refused"
    assert status_of(urllib.request.Request(base, headers={"Origin": "http://example.com"})) == 403, \
        "a browser's request without the token must be refused"
    assert status_of(base + "catalogue.json?token=" + token) == 200

    port = free_port()
    driver = subprocess.Popen(["chromedriver", f"--port={port}"], stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
    wd = f"http://127.0.0.1:{port}"
    for _ in range(100):
        try:
            http("GET", wd + "/status")
            break
        except Exception:
            time.sleep(0.1)
    capabilities = {"capabilities": {"alwaysMatch": {"browserName": "chrome", "goog:chromeOptions": {
        "binary": "/usr/bin/chromium",
        "args": ["--headless=new", "--no-sandbox", "--disable-gpu", "--disable-dev-shm-usage", "--window-size=412,860",
                 f"--user-data-dir={profile}"]}}}}
    session = http("POST", wd + "/session", capabilities)["value"]["sessionId"]
    s = f"{wd}/session/{session}"

    def find(css, wait=20):
        end = time.time() + wait
        while time.time() < end:
            found = http("POST", s + "/elements", {"using": "css selector", "value": css})["value"]
            if found:
                return list(found[0].values())[0]
            time.sleep(0.1)
        fail(f"nothing matches {css} in the page")

    http("POST", s + "/url", {"url": url})
    find('body[data-connection="live"][data-scene="neon"]')
    # A phone's width (412 px) shows every scene's button, the one showing among them.
    hidden = http("POST", s + "/execute/sync", {"script": """
        const width = document.documentElement.clientWidth;
        return [...document.querySelectorAll("#scenes button")]
            .filter(b => { const r = b.getBoundingClientRect(); return r.left < 0 || r.right > width; })
            .map(b => b.textContent);""", "args": []})["value"]
    if hidden:
        fail(f"scene buttons outside a 412 px page: {hidden}")
    # The live mappings playing the scene are listed (docs/LIVE.md); an OSC fader drives one.
    item = find("#mappings li")
    if http("GET", f"{s}/element/{item}/text")["value"] != "osc.fader=neon.bloom_strength:0:2":
        fail("the page should list the mapping osc.fader=neon.bloom_strength:0:2")
    address, fader = b"/vitrine/mod/fader\0\0", b",f\0\0" + struct.pack(">f", 1.0)
    with socket.socket(socket.AF_INET, socket.SOCK_DGRAM) as osc:
        osc.sendto(address + fader, ("127.0.0.1", int(base.split(":")[2].split("/")[0])))
    slider = find('input[data-key="particles"]')
    # The first state push shows the run's value: particles 32, the slider's position 28 of 4..64.
    deadline = time.time() + 10
    while http("GET", f"{s}/element/{slider}/property/value")["value"] != "28":
        if time.time() > deadline:
            fail("the page never showed the run's particles=32")
        time.sleep(0.1)
    http("POST", f"{s}/element/{slider}/value", {"text": "\ue012" * 4})  # focused, Left four times: 32 -> 28

    # A preset saved from the page is offered back, marked as the user's; one the gallery does not have
    # is refused, and the page says why.
    def preset(op, name):
        box = find("#preset-name")
        http("POST", f"{s}/element/{box}/clear", {})
        http("POST", f"{s}/element/{box}/value", {"text": name})
        button = find('[data-preset-op="' + op + '"]')
        http("POST", f"{s}/element/{button}/click", {})

    def script(code):
        return http("POST", s + "/execute/sync", {"script": code, "args": []})["value"]

    def until(what, code, wanted):  # waits up to 10 s for the script's value to hold `wanted`
        deadline = time.time() + 10
        while wanted not in script(code):
            if time.time() > deadline:
                fail(f"{what}: {script(code)}")
            time.sleep(0.1)

    preset("save", "dusk")
    until("the page does not offer the preset it saved",
          'return [...document.querySelectorAll("#preset-list option")].map(o => o.label)', "dusk (yours)")
    preset("apply", "nothing like it")
    until("the page does not say why the gallery refused a preset",
          'return document.querySelector("#message").textContent', "no preset 'nothing like it'")
    script("window.scrollTo(0, 0)")  # the preset box was scrolled into view; the drag below is in viewport pixels

    pad = find("#pad")
    rect = http("GET", f"{s}/element/{pad}/rect")["value"]
    x0, y = int(rect["x"] + rect["width"] * 0.15), int(rect["y"] + rect["height"] * 0.5)
    step = int(rect["width"] * 0.06)
    moves = [{"type": "pointerMove", "duration": 0, "origin": "viewport", "x": x0, "y": y},
             {"type": "pointerDown", "button": 0}]
    moves += [{"type": "pointerMove", "duration": 50, "origin": "viewport", "x": x0 + step * i, "y": y - i}
              for i in range(1, 13)]
    moves += [{"type": "pointerUp", "button": 0}]
    http("POST", s + "/actions", {"actions": [{"type": "pointer", "id": "finger", "parameters": {"pointerType": "touch"},
                                              "actions": moves}]})
    time.sleep(1.0)  # a few frames for the last messages
finally:
    if session:  # ending the session closes the browser; chromedriver stopped first would leave it running
        try:
            urllib.request.urlopen(urllib.request.Request(s, method="DELETE"), timeout=30).close()
        except OSError as e:
            print("the WebDriver session did not end:", e)
    if driver:
        driver.terminate()
        driver.wait(timeout=30)
    run.send_signal(signal.SIGTERM)
    try:
        output, _ = run.communicate(timeout=60)
    except subprocess.TimeoutExpired:
        run.kill()
        fail("vitrine did not stop on SIGTERM")

if run.returncode != 0:
    fail(f"vitrine exited with {run.returncode}:\n{output}")
for _ in range(50):
    if not browsers_left():
        break
    time.sleep(0.1)
else:
    fail(f"Chromium still running after the test (processes {browsers_left()})")
lines = [json.loads(line) for line in open(events)]
sets = [e for e in lines if e["event"] == "remote_set" and e["key"] == "particles"]
releases = [e for e in lines if e["event"] == "release" and e["by"] == "cursor"]
if not sets or sets[-1]["value"] != "28":
    fail(f"the slider should have set particles=28, got {[e['value'] for e in sets]}")
mapped = [e for e in lines if e["event"] == "mapped" and e["by"] == "osc.fader"]
if not mapped or mapped[-1]["value"] != "2":
    fail(f"/vitrine/mod/fader 1 should have set bloom_strength=2 through the mapping, got {mapped}")
if len(releases) < 1:  # a drag draws one tube: one release where it starts
    fail(f"the pad's drag should draw a tube, got {len(releases)} releases")
print(f"ok: particles set to {sets[-1]['value']} in {len(sets)} steps, {len(releases)} tube(s) drawn from the pad")
