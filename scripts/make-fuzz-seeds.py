#!/usr/bin/env python3
"""Writes the fuzz targets' seed corpora from real data (committed under
tests/<stage>/fuzz/seeds/<target>/): what a real matchcast-server sends and
records for the bundled game, and what spectators and browsers send it.

    scripts/make-fuzz-seeds.py build/server/app/matchcast-server

It starts the server on 127.0.0.1 (port 0), reads a few seconds of its
stream as a spectator, records one second of the game (closed with its
index, and once more killed with SIGKILL), and cuts all of it into small
seed files. The ingest targets' seeds (real log fragments and datagrams) are
older and not rewritten here. Run it again when the wire or recording format
changes; keep the files few and small.
"""
import os
import shutil
import signal
import struct
import subprocess
import sys
import tempfile
import time

from ws_client import WsClient  # scripts/ws_client.py

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
GAME = os.path.join(ROOT, 'data', '20261122030423-HELIOS_A_1-vs-HELIOS_B_5.rcg.gz')


def start(server, *args):
    p = subprocess.Popen([server, '--port', '0', '--rcg', GAME, *args], stdout=subprocess.PIPE,
                         stderr=subprocess.DEVNULL, text=True)
    deadline = time.time() + 30
    while time.time() < deadline:
        line = p.stdout.readline()
        if 'http://127.0.0.1:' in line:
            return p, int(line.split('http://127.0.0.1:')[1].split('/')[0])
    p.kill()
    sys.exit('the server did not start')


def write(folder, name, data):
    os.makedirs(folder, exist_ok=True)
    with open(os.path.join(folder, name), 'wb') as f:
        f.write(data if isinstance(data, bytes) else data.encode())


def clear(folder):
    """Empties a seed folder for new seeds, but keeps the crashers found by
    fuzzing (crash-*): they are regression inputs, not seeds from real data."""
    if os.path.isdir(folder):
        for name in os.listdir(folder):
            if not name.startswith('crash-'):
                os.remove(os.path.join(folder, name))


def wrap(kind, number, payload):
    """server/nats/envelope.hpp: u8 kind | u64 number LE | payload."""
    return kind.encode() + struct.pack('<Q', number) + payload


def records(data, start):
    """Splits a recording's bytes after `start` into its records (proto/recording.hpp:
    u32 LE payload size, type, payload, CRC: 9 bytes more than the payload)."""
    out, at = [], start
    while at + 4 <= len(data):
        size = struct.unpack('<I', data[at:at + 4])[0] + 9
        if at + size > len(data):
            break
        out.append(data[at:at + size])
        at += size
    return out


def main():
    if len(sys.argv) != 2:
        sys.exit(__doc__)
    server = os.path.abspath(sys.argv[1])
    tmp = tempfile.mkdtemp(prefix='mc-seeds-')
    try:
        # 1. Three seconds of the live stream: hello, metadata, frames, events.
        p, port = start(server, '--record-dir', '')
        spectator = WsClient(port, timeout=5)
        texts, frames = [], []
        end = time.time() + 3
        while time.time() < end:
            op, payload = spectator.read()
            if op == 1:
                texts.append(payload)
            elif op == 2:
                frames.append(payload)
        keys = frames[:1]  # a joiner's first frame is the keyframe of the current group
        upgrade = spectator.request
        p.send_signal(signal.SIGTERM)
        p.wait(10)
        hello = texts[0]
        kinds = {}
        for t in texts[1:]:
            kind = t.split(b'"type":"', 1)[1].split(b'"', 1)[0] if b'"type":"' in t else b'?'
            kinds.setdefault(kind, t)
        deltas = frames[1:4]

        # 2. Half a second recorded (ten frames: a seed the fuzzer mutates
        # must stay small, as every input is read, scanned and decoded
        # whole), closed with its index; one killed mid-recording.
        rec = os.path.join(tmp, 'rec')
        os.makedirs(rec)
        p, port = start(server, '--record-dir', rec, '--record-max-bytes', '0', '--record-max-age', '0')
        time.sleep(0.6)
        p.send_signal(signal.SIGTERM)
        p.wait(10)
        closed = open(os.path.join(rec, sorted(os.listdir(rec))[0]), 'rb').read()
        killed_dir = os.path.join(tmp, 'killed')
        os.makedirs(killed_dir)
        p, port = start(server, '--record-dir', killed_dir, '--record-max-bytes', '0', '--record-max-age', '0')
        time.sleep(1.7)
        p.send_signal(signal.SIGKILL)
        p.wait(10)
        killed = open(os.path.join(killed_dir, os.listdir(killed_dir)[0]), 'rb').read()
        header_size = 16
        parts = records(closed, header_size)  # hello, chunks..., index (then the trailer)
        prefix = closed[:header_size] + parts[0]
        index_at = len(closed) - len(parts[-1]) - 16  # the index record, then a 16-byte trailer

        # proto: frames, JSON messages, recording records.
        d = os.path.join(ROOT, 'tests/proto/fuzz/seeds/proto_frame_decoder_fuzz')
        clear(d)
        for i, k in enumerate(keys[:1]):
            write(d, f'keyframe-{i}', k)
        for i, f in enumerate(deltas):
            write(d, f'delta-{i}', f)
        write(d, 'hello.json', hello)
        for kind, t in sorted(kinds.items()):
            write(d, f'control-{kind.decode()}.json', t)
        if len(parts) > 2:
            write(d, 'record-chunk', parts[1])
            write(d, 'record-index', parts[-1])

        # replay: the recording reader (first byte: what the rest is).
        d = os.path.join(ROOT, 'tests/replay/fuzz/seeds/recording_reader')
        clear(d)
        write(d, '0-closed', b'\x00' + closed)
        write(d, '0-killed', b'\x00' + killed)
        write(d, '1-chunks', b'\x01' + closed[len(prefix):index_at])
        write(d, '2-index', b'\x02' + closed[index_at:])
        write(d, '3-overwrite', b'\x03' + b'\x40\x00' + parts[1][:64] if len(parts) > 1 else b'\x03')

        # replay: what spectators send (the page's and the viewer's messages).
        d = os.path.join(ROOT, 'tests/replay/fuzz/seeds/spectator_messages')
        clear(d)
        write(d, 'replay-controls', '\n'.join([
            '{"type":"replay","action":"pause"}', '{"type":"replay","action":"play"}',
            '{"type":"replay","action":"seek","time":12}', '{"type":"replay","action":"speed","speed":2}',
            '{"type":"replay","action":"next_goal"}', '{"type":"replay","action":"prev_goal"}',
            '{"type":"replay","action":"toggle"}']))
        write(d, 'timeshift', '{"type":"timeshift","action":"seek","time":1200}\n{"type":"timeshift","action":"live"}')
        write(d, 'seek-far', '{"type":"replay","action":"seek","time":1e300}\n{"type":"replay","action":"speed","speed":-0.0}')

        # relay: requests as they reach the router.
        d = os.path.join(ROOT, 'tests/relay/fuzz/seeds/http_request')
        clear(d)
        write(d, 'upgrade', upgrade)
        write(d, 'upgrade-replay', upgrade.replace(b'GET /ws ', b'GET /ws?recording=live-20261122-030423.mcrec '))
        write(d, 'browser-page', 'GET / HTTP/1.1\r\nHost: 127.0.0.1:8080\r\nConnection: keep-alive\r\n'
              'sec-ch-ua: "Chromium";v="120"\r\nUpgrade-Insecure-Requests: 1\r\nUser-Agent: Mozilla/5.0 (X11; Linux x86_64) '
              'AppleWebKit/537.36 (KHTML, like Gecko) Chrome/120.0.0.0 Safari/537.36\r\nAccept: text/html,application/xhtml+xml,'
              'application/xml;q=0.9,*/*;q=0.8\r\nAccept-Encoding: gzip, deflate, br\r\nAccept-Language: en-US,en;q=0.9\r\n\r\n')
        write(d, 'script', 'GET /src/main.js?v=3 HTTP/1.1\r\nHost: 127.0.0.1:8080\r\nReferer: http://127.0.0.1:8080/\r\n\r\n')
        write(d, 'control', 'POST /control/feed/stop?channel=live HTTP/1.1\r\nHost: 127.0.0.1\r\n'
              'Authorization: Bearer secret\r\nContent-Length: 0\r\n\r\n')
        write(d, 'metrics', 'HEAD /metrics HTTP/1.1\r\nHost: 127.0.0.1\r\n\r\nGET /channels HTTP/1.1\r\n\r\n')

        # nats: the envelopes an origin publishes for these messages.
        d = os.path.join(ROOT, 'tests/nats/fuzz/seeds/envelope')
        clear(d)
        write(d, 'hello', wrap('H', 1, hello))
        if keys:
            write(d, 'keyframe', wrap('K', 2, keys[0]))
            write(d, 'snapshot', wrap('S', 2, struct.pack('<I', len(hello)) + hello + keys[0]))
        if deltas:
            write(d, 'delta', wrap('D', 3, deltas[0]))
        if kinds:
            write(d, 'control', wrap('C', 4, sorted(kinds.items())[0][1]))

        # relay: what a browser's WebSocket sends (masked frames).
        d = os.path.join(ROOT, 'tests/relay/fuzz/seeds/ws_inbound')
        clear(d)
        write(d, 'timeshift', b'\x07' + WsClient.text_frame('{"type":"timeshift","action":"seek","time":1200}'))
        write(d, 'replay', b'\x10' + WsClient.text_frame('{"type":"replay","action":"speed","speed":2}') +
              bytes([0x89, 0x80]) + os.urandom(4) + bytes([0x88, 0x82]) + b'\x00\x00\x00\x00\x03\xe8')
    finally:
        shutil.rmtree(tmp, ignore_errors=True)


if __name__ == '__main__':
    main()
