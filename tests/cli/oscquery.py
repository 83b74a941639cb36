#!/usr/bin/env python3
"""oscquery.py VITRINE OUTDIR: an OSCQuery client against a headless --remote run, over real HTTP, UDP
and WebSocket. The namespace holds every parameter `--list-params` lists, with its type and range; a
value set over OSC shows in VALUE; LISTEN streams changes as binary OSC and IGNORE stops them;
malformed and oversized queries are refused; without the token only addresses OSC itself trusts get
in, never a browser's request; with no Avahi daemon reachable, one line says so and all else runs."""
import os
import re
import socket
import subprocess
import sys
import time

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "tools"))
from oscquery_client import WebSocket, get, get_json, osc_message, parse_osc, send_osc  # noqa: E402

vitrine, out = sys.argv[1], sys.argv[2]
os.makedirs(out, exist_ok=True)


def fail(why):
    print("FAIL:", why)
    sys.exit(1)


def until(condition, what, seconds=5.0):
    deadline = time.monotonic() + seconds
    while time.monotonic() < deadline:
        result = condition()
        if result:
            return result
        time.sleep(0.02)
    fail(f"timed out waiting for {what}")


def listed_params():
    """{scene: {key: type text}} from --list-params (a wrapped type continues on the next lines)."""
    text = subprocess.run([vitrine, "--list-params"], check=True, capture_output=True, text=True).stdout
    scenes, scene, last, columns = {}, None, None, None
    for line in text.splitlines():
        header = re.match(r"^(\w+): \d+ parameters", line)
        if header:
            scene = header.group(1)
            scenes[scene] = {}
            continue
        row = re.match(r"^  (\w+)( +)(.*?) +default ", line)
        if scene and row and not line.startswith("  action "):
            last = row.group(1)
            scenes[scene][last] = row.group(3)
            columns = (len(row.group(1)) + len(row.group(2)) + 2, line.index(" default ") + 1)
            continue
        if last and columns and line.startswith(" " * columns[0]) and scenes[scene][last].endswith("|"):
            scenes[scene][last] += line[columns[0]:columns[1]].strip()
        elif line.strip() == "" or line.startswith("presets"):
            last = None
    return scenes


def check_namespace(root, listed):
    vitrine_node = root["CONTENTS"]["vitrine"]["CONTENTS"]
    checked = 0
    for scene, params in listed.items():
        contents = vitrine_node[scene]["CONTENTS"]
        described = {k for k, v in contents.items() if v.get("ACCESS") == 3}
        if described != set(params):
            fail(f"{scene}: the namespace has {sorted(described)}, --list-params {sorted(params)}")
        for key, kind in params.items():
            node = contents[key]
            where = f"{scene}.{key} ({kind})"
            if node["FULL_PATH"] != f"/vitrine/{scene}/{key}":
                fail(f"{where}: FULL_PATH {node['FULL_PATH']}")
            number = re.match(r"(int|float) (-?[\d.e+-]+)\.\.(-?[\d.e+-]+)$", kind)
            if number:
                want = "i" if number.group(1) == "int" else "f"
                low, high = float(number.group(2)), float(number.group(3))
                got = node["RANGE"][0]
                if node["TYPE"] != want or abs(got["MIN"] - low) > 1e-6 * max(1, abs(low)) or \
                        abs(got["MAX"] - high) > 1e-6 * max(1, abs(high)):
                    fail(f"{where}: TYPE {node['TYPE']} RANGE {got}")
            elif kind == "bool":
                if node["TYPE"] != "T" or not isinstance(node["VALUE"][0], bool):
                    fail(f"{where}: {node}")
            elif kind.startswith("choice ") or kind.startswith("file or "):
                choices = kind.split(" ", 2)[-1].split("|") if kind.startswith("file") else kind[7:].split("|")
                if node["TYPE"] != "s" or node["RANGE"][0]["VALS"] != choices:
                    fail(f"{where}: TYPE {node['TYPE']} RANGE {node.get('RANGE')}")
            elif node["TYPE"] != "s":
                fail(f"{where}: TYPE {node['TYPE']}")
            checked += 1
    return checked


def value_of(port, path, **kwargs):
    return get_json(port, path + "?VALUE", **kwargs)["VALUE"][0]


def next_value(ws, seconds=5):
    frame = ws.receive(seconds)
    if frame is None:
        return None
    opcode, payload = frame
    if opcode != 2:
        fail(f"a text frame where binary OSC was expected: {payload[:100]!r}")
    return parse_osc(payload)


def own_address():
    """A non-loopback address of this computer, or None."""
    with socket.socket(socket.AF_INET, socket.SOCK_DGRAM) as probe:
        try:
            probe.connect(("192.0.2.123", 9))  # no packet is sent: only the route is looked up
            address = probe.getsockname()[0]
        except OSError:
            return None
    return None if address.startswith("127.") else address


listed = listed_params()
log_path = os.path.join(out, "vitrine.log")
env = dict(os.environ, DBUS_SYSTEM_BUS_ADDRESS="unix:path=" + os.path.join(out, "no-bus"))  # no Avahi here
with open(log_path, "w") as log:
    run = subprocess.Popen([vitrine, "--headless", "--scene", "kifs", "--size", "32x18", "--frames", "100000000",
                            "--remote", "--remote-bind", "0.0.0.0:0", "--out", os.path.join(out, "x.exr")],
                           stdout=log, stderr=subprocess.STDOUT, env=env)
try:
    def logged():
        with open(log_path) as f:
            return f.read()
    found = until(lambda: re.search(r"remote control on 0\.0\.0\.0:(\d+)", logged()), "the remote control")
    port = int(found.group(1))
    token = re.search(r"token=([0-9a-f]{32})", logged()).group(1)
    started = time.monotonic()

    # The namespace against --list-params.
    root = get_json(port, "/")
    checked = check_namespace(root, listed)
    print(f"namespace: {checked} parameters of {len(listed)} scenes match --list-params")
    info = get_json(port, "/?HOST_INFO")
    if info["OSC_PORT"] != port or info["OSC_TRANSPORT"] != "UDP" or not info["EXTENSIONS"]["LISTEN"]:
        fail(f"HOST_INFO: {info}")

    # A value set over OSC, at the advertised path with the advertised type, is VALUE.
    send_osc(port, osc_message("/vitrine/kifs/step", 3))
    until(lambda: value_of(port, "/vitrine/kifs/step") == 3, "step=3 over OSC in VALUE")
    print("OSC /vitrine/kifs/step i 3: VALUE [3]")

    # LISTEN: changes arrive as binary OSC; after IGNORE they stop (a listened value changed later
    # arrives first, so nothing of the ignored one was on its way).
    ws = WebSocket(port, "/")
    if ws.status != 101:
        fail(f"the OSCQuery socket: {ws.status}")
    ws.command("LISTEN", "/vitrine/kifs/step")
    ws.command("LISTEN", "/vitrine/kifs/fold")
    sent = time.monotonic()
    send_osc(port, osc_message("/vitrine/kifs/step", 5))
    got = next_value(ws)
    if got != ("/vitrine/kifs/step", [5]):
        fail(f"after LISTEN, a change of step: {got}")
    print(f"LISTEN: step=5 streamed {1000 * (time.monotonic() - sent):.0f} ms after the OSC message")
    ws.command("IGNORE", "/vitrine/kifs/step")
    ws.command("NOT A COMMAND", "/vitrine/kifs/step")  # ignored: the socket stays
    time.sleep(0.05)  # the socket's commands are read in order, before this OSC datagram is even sent
    send_osc(port, osc_message("/vitrine/kifs/step", 6))
    until(lambda: value_of(port, "/vitrine/kifs/step") == 6, "step=6 in VALUE")
    send_osc(port, osc_message("/vitrine/kifs/fold", 1.25))
    got = next_value(ws)
    if got is None or got[0] != "/vitrine/kifs/fold" or abs(got[1][0] - 1.25) > 1e-6:
        fail(f"after IGNORE of step, the next value should be fold=1.25: {got}")
    print("IGNORE: step=6 not streamed; fold=1.25 streamed")

    # OSC over the socket itself, as ossia sends it.
    ws.send(osc_message("/vitrine/kifs/step", 2))
    until(lambda: value_of(port, "/vitrine/kifs/step") == 2, "step=2 sent over the WebSocket")
    # A text message over the 4 KiB limit closes the socket.
    ws.send("x" * 5000)
    if ws.receive(3) is not None:
        fail("an oversized WebSocket message should close the socket")
    ws.close()
    print("OSC over the socket sets step=2; a 5,000-byte message closes the socket")

    # Malformed and oversized queries: a status, and the server goes on.
    for target, status in [("/vitrine/kifs/step?BOGUS", 400), ("/vitrine/kifs/step?VALUE&TYPE", 400),
                           ("/vitrine//kifs", 400), ("/vitrine/kifs/nope", 404), ("/vitrine/kifs?VALUE", 204),
                           ("/vitrine/kifs/step?" + "A" * 600, 400), ("/" + "a" * 9000, 413)]:
        got, _ = get(port, target)
        if got != status:
            fail(f"GET {target[:60]}: {got}, expected {status}")
    if value_of(port, "/vitrine/kifs/step") != 2:
        fail("the server should answer after refusing")
    print("malformed queries: 400, unknown: 404, no value: 204, 9 KB of target: 413")

    # Without the token: loopback is trusted (as for OSC), a browser's request never is, and an
    # address beyond loopback gets nothing until it sends the token over OSC.
    if get(port, "/", headers={"Origin": "http://attacker.example"})[0] != 403:
        fail("a request with Origin (a browser's page) without the token must be refused")
    if get(port, "/", headers={"Host": "attacker.example"})[0] != 403:
        fail("a request naming another host (DNS rebinding) without the token must be refused")
    if get(port, "/catalogue.json")[0] != 403:
        fail("the page's catalogue still needs the token")
    source = own_address()
    if source is None:
        print("SKIP: this machine has no address beyond loopback; tokenless refusal from the network not tried")
    else:
        if get(port, "/vitrine/kifs/step?VALUE", host=source, source=source)[0] != 403:
            fail(f"a tokenless request from {source} (not an allowed network) must be refused")
        if WebSocket(port, "/", host=source, source=source).status != 403:
            fail(f"a tokenless socket from {source} must be refused")
        send_osc(port, osc_message("/vitrine/kifs/step", 7), host=source, source=source)  # refused too
        if get(port, f"/vitrine/kifs/step?VALUE&token={token}", host=source, source=source)[0] != 200:
            fail("the token opens the namespace from anywhere")
        send_osc(port, osc_message("/vitrine/token", token), host=source, source=source)
        until(lambda: get(port, "/vitrine/kifs/step?VALUE", host=source, source=source)[0] == 200,
              "the address trusted after /vitrine/token")
        if value_of(port, "/vitrine/kifs/step") != 2:
            fail("OSC from an untrusted address must not have set step")
        print(f"from {source}: 403 without the token, 200 with it, and without it once OSC's /vitrine/token was sent")

    mdns = until(lambda: re.search(r"mDNS: .*", logged()), "the mDNS line")
    if "no Avahi daemon" not in mdns.group(0):
        fail(f"with no D-Bus, the mDNS line should say no daemon runs: {mdns.group(0)}")
    print(f"without a daemon: \"{mdns.group(0)}\", and everything above ran")
    print(f"all checks in {time.monotonic() - started:.1f} s")
finally:
    run.terminate()
    try:
        run.wait(timeout=20)
    except subprocess.TimeoutExpired:
        run.kill()
if run.returncode not in (0, -15):
    fail(f"vitrine exited with {run.returncode}: {open(log_path).read()[-2000:]}")
print("PASS")
