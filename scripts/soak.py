#!/usr/bin/env python3
"""The soak with faults behind scripts/soak.sh (see there). Everything on
loopback, every process started here stopped here, every wait bounded."""
import argparse
import json
import os
import random
import re
import signal
import socket
import struct
import subprocess
import sys
import threading
import time
import urllib.request

from ws_client import WsClient  # scripts/ws_client.py

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
GAME = os.path.join(ROOT, 'data', '20261122030423-HELIOS_A_1-vs-HELIOS_B_5.rcg.gz')


def log(msg):
    print(time.strftime('%H:%M:%S ') + msg, flush=True)


def free_udp_port():
    s = socket.socket(socket.AF_INET, socket.SOCK_DGRAM)
    s.bind(('127.0.0.1', 0))
    port = s.getsockname()[1]
    s.close()
    return port


def proc_sample(pid):
    """(RSS in kB, open file descriptors, RSS split {'anon','file'} in kB) of a process."""
    rss, split = 0, {}
    with open(f'/proc/{pid}/status') as f:
        for line in f:
            if line.startswith('VmRSS:'):
                rss = int(line.split()[1])
            elif line.startswith('RssAnon:'):
                split['anon'] = int(line.split()[1])
            elif line.startswith('RssFile:'):
                split['file'] = int(line.split()[1])
    return rss, len(os.listdir(f'/proc/{pid}/fd')), split


def metrics(port):
    text = urllib.request.urlopen(f'http://127.0.0.1:{port}/metrics', timeout=5).read().decode()
    out = {}
    for line in text.splitlines():
        if line and not line.startswith('#') and '{' not in line:
            name, value = line.rsplit(' ', 1)
            out[name] = float(value)
    return out


def frame_header(payload):
    """(seq, time, keyframe) from a frame header (proto/SPEC.md section 2)."""
    # magic, major, minor, flags (bit 0 keyframe), u32 seq at 4, i32 time at 8.
    seq, time_ = struct.unpack_from('<Ii', payload, 4)
    return seq, time_, bool(payload[3] & 1)


class ReplaySeeker(threading.Thread):
    """A replay spectator that seeks at random for `seconds`: after each seek
    the first frame must be a keyframe at (or just after) the time asked."""

    def __init__(self, port, name, first, last, seconds, results):
        super().__init__(daemon=True)
        self.port, self.name, self.first, self.last = port, name, first, last
        self.seconds, self.results = seconds, results

    def run(self):
        ok = bad = 0
        errors = []
        try:
            ws = WsClient(self.port, '/ws?recording=' + self.name)
            ws.s.settimeout(10)
            end = time.time() + self.seconds
            while time.time() < end:
                target = random.randint(self.first, self.last)
                ws.send(json.dumps({'type': 'replay', 'action': 'seek', 'time': target}))
                deadline = time.time() + 5
                seen = None
                while time.time() < deadline:
                    op, payload = ws.read()
                    if op != 2:
                        continue
                    seq, t, key = frame_header(payload)
                    if key and target <= t <= target + 20:
                        seen = t
                        break
                if seen is None:
                    bad += 1
                    errors.append(f'seek {target}: no keyframe at it within 5 s')
                else:
                    ok += 1
                time.sleep(random.uniform(0.5, 3))
            ws.close()
        except Exception as e:  # noqa: BLE001 - reported, not raised
            errors.append(f'{type(e).__name__}: {e}')
            bad += 1
        self.results.append({'recording': self.name, 'seeks_ok': ok, 'seeks_bad': bad, 'errors': errors[:5]})


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument('--minutes', type=float, required=True)
    ap.add_argument('--build', default=os.path.join(ROOT, 'build'))
    ap.add_argument('--out', default=os.path.join(ROOT, 'test-output', 'soak'))
    ap.add_argument('--clients', type=int, default=2000)
    ap.add_argument('--churn', type=int, default=20)
    ap.add_argument('--stalled', type=float, default=0.01)
    ap.add_argument('--feed-restart-every', type=float, default=120)
    ap.add_argument('--burst', type=int, default=500)
    ap.add_argument('--burst-every', type=float, default=300)
    ap.add_argument('--burst-stay', type=float, default=60)
    ap.add_argument('--warmup', type=float, default=None, help='seconds before RSS/fd must be flat')
    ap.add_argument('--server', default=None, help='another matchcast-server binary, to compare two builds side by side')
    a = ap.parse_args()
    duration = a.minutes * 60
    warmup = a.warmup if a.warmup is not None else min(300, duration / 3)
    bins = {n: os.path.join(a.build, p) for n, p in {
        'server': 'server/app/matchcast-server', 'feeder': 'server/tools/feeder/matchcast-feeder',
        'loadgen': 'server/tools/loadgen/matchcast-loadgen',
        'check': 'server/tools/recording_check/matchcast-recording-check'}.items()}
    if a.server:
        bins['server'] = a.server
    for n, p in bins.items():
        if not os.access(p, os.X_OK):
            sys.exit(f'soak: {p} is missing (scripts/soak.sh builds it)')
    run = os.path.join(a.out, time.strftime('run-%Y%m%d-%H%M%S'))
    rec = os.path.join(run, 'recordings')
    os.makedirs(rec)
    procs = []

    def spawn(args, out, **kw):
        p = subprocess.Popen(args, stdout=out, stderr=subprocess.STDOUT if out != subprocess.PIPE else open(
            os.path.join(run, os.path.basename(args[0]) + '.err'), 'a'), **kw)
        procs.append(p)
        return p

    feed_port = free_udp_port()

    def start_feeder():
        return spawn([bins['feeder'], GAME, '--port', str(feed_port), '--loop'],
                     open(os.path.join(run, 'feeder.log'), 'a'))

    try:
        feeder = start_feeder()
        server_log = open(os.path.join(run, 'server.log'), 'w')
        server = subprocess.Popen([bins['server'], '--port', '0', '--rcg', f'udp://127.0.0.1:{feed_port}',
                                   '--record-dir', rec, '--record-max-bytes', '0', '--record-max-age', '0',
                                   '--max-connections-per-ip', '0', '--threads', '2'],
                                  stdout=subprocess.PIPE, stderr=server_log, text=True)
        procs.append(server)
        port = None
        deadline = time.time() + 60
        while time.time() < deadline and port is None:
            line = server.stdout.readline()
            m = re.search(r'http://127\.0\.0\.1:(\d+)/', line)
            if m:
                port = int(m.group(1))
        if port is None:
            sys.exit('soak: the server did not start (see server.log)')
        log(f'server pid {server.pid} on port {port}, feeder on udp {feed_port}; output in {run}')
        loadgen_out = open(os.path.join(run, 'loadgen.jsonl'), 'w')
        loadgen = spawn([bins['loadgen'], '--port', str(port), '--soak', '-n', str(a.clients), '--stalled', str(a.stalled),
                         '--churn', str(a.churn), '--burst', str(a.burst), '--burst-every', str(a.burst_every),
                         '--burst-stay', str(a.burst_stay), '--duration', str(duration), '--threads', '2',
                         '--header-only', '--ramp', '500', '--report-every', '10', '--nice', '10'], loadgen_out)
        start = time.time()
        samples, replay_results, seekers = [], [], []
        restarts = 0
        next_restart = start + a.feed_restart_every
        next_sample = start + 10
        next_replay = start + min(150, duration / 2)
        while loadgen.poll() is None and time.time() < start + duration + 120:
            time.sleep(0.5)
            now = time.time()
            if now >= next_restart and now < start + duration - 10:
                feeder.send_signal(signal.SIGKILL)
                feeder.wait(10)
                time.sleep(1)
                feeder = start_feeder()
                restarts += 1
                next_restart += a.feed_restart_every
                log(f'feed restarted ({restarts})')
            if now >= next_sample:
                rss, fds, split = proc_sample(server.pid)
                t = now - start
                # The steady point of each burst cycle: just before the next burst.
                phase = t % a.burst_every if a.burst_every > 0 else 0
                steady = a.burst_every > 0 and phase >= a.burst_every - 12
                try:
                    mt = metrics(port)
                except Exception:  # noqa: BLE001
                    mt = {}
                samples.append({'t': round(t, 1), 'rss_kb': rss, 'fds': fds, 'steady': steady,
                                'anon_kb': split.get('anon', 0), 'file_kb': split.get('file', 0),
                                'clients': mt.get('matchcast_clients'),
                                'heap_in_use': mt.get('matchcast_heap_in_use_bytes'),
                                'heap_free': mt.get('matchcast_heap_free_bytes')})
                next_sample += 10
            if now >= next_replay:
                try:
                    lst = json.load(urllib.request.urlopen(f'http://127.0.0.1:{port}/recordings', timeout=5))['recordings']
                    names = sorted(r['name'] for r in lst)
                    if len(names) >= 2:
                        name = names[-2]  # the newest finished game (the last one is being written)
                        out = subprocess.run([bins['check'], os.path.join(rec, name)], capture_output=True, text=True).stdout
                        m = re.search(r'cycles (\d+)-(\d+)', out)
                        if m:
                            s = ReplaySeeker(port, name, int(m.group(1)), int(m.group(2)), 60, replay_results)
                            s.start()
                            seekers.append(s)
                            log(f'replay spectator seeking in {name}')
                except Exception as e:  # noqa: BLE001
                    replay_results.append({'recording': '?', 'seeks_ok': 0, 'seeks_bad': 1, 'errors': [str(e)]})
                next_replay += a.burst_every if a.burst_every > 0 else 300
        loadgen.wait(60)
        for s in seekers:
            s.join(70)
        time.sleep(2)
        final_metrics = metrics(port)
        rss_end, fds_end, _ = proc_sample(server.pid)
        server.send_signal(signal.SIGTERM)
        server.wait(30)
        feeder.send_signal(signal.SIGTERM)
        feeder.wait(10)
    finally:
        for p in procs:
            if p.poll() is None:
                p.kill()
                p.wait()

    # ---- the figures and the checks
    reports = [json.loads(l) for l in open(os.path.join(run, 'loadgen.jsonl')) if l.startswith('{')]
    final = reports[-1] if reports else {}
    h, st = final.get('healthy', {}), final.get('stalled', {})
    text = open(os.path.join(run, 'server.log')).read()
    stuck = [int(x) for x in re.findall(r'write stuck (\d+) ms', text)]
    feed_lost = text.count('"event":"feed_lost"')
    feed_back = text.count('"event":"feed_back"')
    files = sorted(os.path.join(rec, f) for f in os.listdir(rec) if f.endswith('.mcrec'))
    check = subprocess.run([bins['check'], *files], capture_output=True, text=True) if files else None
    after = [s for s in samples if s['t'] >= warmup]
    steady = [s for s in after if s['steady']] or after

    def spread(key):
        vals = [s[key] for s in steady]
        return (max(vals) - min(vals)) / min(vals) if vals else float('nan')

    checks = []

    def expect(name, ok, figure):
        checks.append((name, bool(ok), figure))

    expect('RSS flat after warm-up (steady points, within 2 %)', spread('rss_kb') <= 0.02,
           f"{len(steady)} points: {min(s['rss_kb'] for s in steady) / 1024:.1f}-{max(s['rss_kb'] for s in steady) / 1024:.1f} MB "
           f"({spread('rss_kb') * 100:.2f} %)" if steady else 'no samples')
    # Not a check, the RSS taken apart: the heap and other anonymous memory
    # (where a leak would show), and the pages of the program's and its
    # libraries' files (code paged in as new paths run for the first time).
    if steady and all('anon_kb' in s for s in steady):
        print(f"RSS at the steady points: anonymous {min(s['anon_kb'] for s in steady) / 1024:.1f}-"
              f"{max(s['anon_kb'] for s in steady) / 1024:.1f} MB ({spread('anon_kb') * 100:.2f} %), files "
              f"{min(s['file_kb'] for s in steady) / 1024:.1f}-{max(s['file_kb'] for s in steady) / 1024:.1f} MB "
              f"({spread('file_kb') * 100:.2f} %)")
    # Not a check either: the heap as glibc counts it. A leak grows what is
    # in use; what is free inside the heap is fragmentation the trims leave.
    if steady and all(s.get('heap_in_use') for s in steady):
        print(f"heap at the steady points: in use {min(s['heap_in_use'] for s in steady) / 2**20:.2f}-"
              f"{max(s['heap_in_use'] for s in steady) / 2**20:.2f} MB, free inside it "
              f"{min(s['heap_free'] for s in steady) / 2**20:.2f}-{max(s['heap_free'] for s in steady) / 2**20:.2f} MB")
    if final_metrics.get('matchcast_heap_trims_total'):
        print(f"heap trims: {final_metrics['matchcast_heap_trims_total']:.0f}, "
              f"{final_metrics.get('matchcast_heap_trim_seconds_total', 0) * 1e3 / final_metrics['matchcast_heap_trims_total']:.2f} ms each on average")
    expect('open fds flat after warm-up (steady points, within 2 %)', spread('fds') <= 0.02,
           f"{min(s['fds'] for s in steady)}-{max(s['fds'] for s in steady)} ({spread('fds') * 100:.2f} %)" if steady else 'no samples')
    healthy_gaps = h.get('gaps', 0) - h.get('resync_gaps', 0)
    expect('no healthy spectator with a sequence gap (other than resyncs at feed restarts)',
           healthy_gaps == 0 and h.get('out_of_order', 1) == 0 and h.get('decode_errors', 1) == 0,
           f"{h.get('frames', 0)} frames, {h.get('gaps', 0)} gaps of which {h.get('resync_gaps', 0)} resyncs at a keyframe "
           f"after a feed message, {h.get('out_of_order', '?')} out of order, {h.get('decode_errors', '?')} errors")
    expect('no healthy spectator refused or closed by the server',
           h.get('failed', 1) == 0 and h.get('closed_by_server', 1) == 0,
           f"{h.get('connected', 0)} connections, {h.get('failed', '?')} failed, {h.get('closed_by_server', '?')} closed by the server")
    expect('every stalled spectator cut off (client side) and within 10 s of its write stalling (server side)',
           st.get('not_cut', 1) == 0 and st.get('cut', 0) > 0 and stuck and max(stuck) <= 10000,
           f"{st.get('connected', 0)} stalled, {st.get('cut', 0)} found cut, {st.get('not_cut', '?')} not cut; "
           f"server: {len(stuck)} closed, write stuck {min(stuck) if stuck else '?'}-{max(stuck) if stuck else '?'} ms")
    expect('every recording readable from end to end', check is not None and check.returncode == 0,
           f"{len(files)} files" + (f"; {sum(1 for l in check.stdout.splitlines() if 'indexed' in l)} with their index" if check else ''))
    expect('feed restarts seen by the server', feed_lost >= restarts and feed_back >= restarts,
           f"{restarts} restarts; server logged {feed_lost} feed_lost, {feed_back} feed_back")
    replay_bad = sum(r['seeks_bad'] for r in replay_results)
    expect('replay spectator seeks land on a keyframe at the time asked', replay_results and replay_bad == 0,
           f"{sum(r['seeks_ok'] for r in replay_results)} seeks ok, {replay_bad} bad in {len(replay_results)} sessions")
    conns = final_metrics.get('matchcast_connections_total', -1)
    counted = h.get('connected', 0) + st.get('connected', 0) + len(replay_results)
    # A client that gave up mid-upgrade (a burst leaving, the run's end)
    # may have been counted by the relay without seeing the 101: the relay
    # may count up to that many more, never fewer.
    abandoned = h.get('abandoned', 0) + st.get('abandoned', 0)
    slow = final_metrics.get('matchcast_closed_slow_total', -1)
    open_stalled = final.get('open', {}).get('stalled', 0)
    expect('/metrics agrees with the load generator',
           counted <= conns <= counted + abandoned and final_metrics.get('matchcast_clients', -1) == 0 and
           st.get('cut', 0) <= slow <= st.get('cut', 0) + open_stalled,
           f"connections_total {conns:.0f} vs loadgen {h.get('connected', 0)} + {st.get('connected', 0)} stalled + "
           f"{len(replay_results)} replay = {counted} (+ up to {abandoned} abandoned mid-upgrade); clients now {final_metrics.get('matchcast_clients', -1):.0f}; "
           f"closed_slow_total {slow:.0f} vs {st.get('cut', 0)} cut (+{open_stalled} still stalled at the end)")

    summary = {'run': run, 'minutes': a.minutes, 'clients': a.clients, 'samples': samples, 'final_loadgen': final,
               'final_metrics': final_metrics, 'replays': replay_results, 'stuck_ms': stuck,
               'recordings': check.stdout.splitlines() if check else [],
               'checks': [{'check': c, 'ok': ok, 'figure': f} for c, ok, f in checks]}
    json.dump(summary, open(os.path.join(run, 'summary.json'), 'w'), indent=1)
    print()
    print(f'soak: {a.minutes:g} min, {a.clients} spectators (+{a.burst} every {a.burst_every:g} s for {a.burst_stay:g} s), '
          f'churn {a.churn}/s, {a.stalled * 100:g} % stalled, feed restarted every {a.feed_restart_every:g} s')
    print(f"      delay p50 {h.get('delay_p50_ms', '?')} ms, p99 {h.get('delay_p99_ms', '?')} ms, max {h.get('delay_max_ms', '?')} ms; "
          f"server at the end: RSS {rss_end / 1024:.1f} MB, {fds_end} fds")
    for c, ok, f in checks:
        print(f"  {'PASS' if ok else 'FAIL'}  {c}: {f}")
    print(f'details: {run}/summary.json')
    sys.exit(0 if all(ok for _, ok, _ in checks) else 1)


if __name__ == '__main__':
    main()
