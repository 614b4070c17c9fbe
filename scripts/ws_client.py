"""A minimal WebSocket client for the scripts (soak.py, make-fuzz-seeds.py):
the upgrade, unmasked server frames in, masked text frames out (what a
browser sends). Loopback tools only: no TLS, no fragments, no extensions."""
import base64
import os
import socket
import struct


class WsClient:
    def __init__(self, port, target='/ws', timeout=10):
        self.s = socket.create_connection(('127.0.0.1', port), timeout=timeout)
        key = base64.b64encode(os.urandom(16)).decode()
        # Kept: the fuzz seeds use the exact request as an HTTP sample.
        self.request = (f'GET {target} HTTP/1.1\r\nHost: 127.0.0.1:{port}\r\nUpgrade: websocket\r\n'
                        f'Connection: Upgrade\r\nSec-WebSocket-Key: {key}\r\nSec-WebSocket-Version: 13\r\n'
                        f'Origin: http://127.0.0.1:{port}\r\n\r\n').encode()
        self.s.sendall(self.request)
        self.buf = b''
        while b'\r\n\r\n' not in self.buf:
            chunk = self.s.recv(4096)
            if not chunk:
                raise EOFError('closed during the upgrade')
            self.buf += chunk
        head, self.buf = self.buf.split(b'\r\n\r\n', 1)
        if not head.startswith(b'HTTP/1.1 101'):
            raise RuntimeError(head.split(b'\r\n')[0].decode())

    def _need(self, n):
        while len(self.buf) < n:
            chunk = self.s.recv(65536)
            if not chunk:
                raise EOFError('closed')
            self.buf += chunk

    def read(self):
        """(opcode, payload) of the next message."""
        self._need(2)
        op, n, at = self.buf[0] & 0x0F, self.buf[1] & 0x7F, 2
        if n == 126:
            self._need(4)
            n, at = struct.unpack('>H', self.buf[2:4])[0], 4
        elif n == 127:
            self._need(10)
            n, at = struct.unpack('>Q', self.buf[2:10])[0], 10
        self._need(at + n)
        payload, self.buf = self.buf[at:at + n], self.buf[at + n:]
        return op, payload

    @staticmethod
    def text_frame(text):
        """The bytes of a masked client text frame."""
        data, mask = text.encode(), os.urandom(4)
        head = bytes([0x81, 0x80 | len(data)]) if len(data) < 126 else bytes([0x81, 0xFE]) + struct.pack('>H', len(data))
        return head + mask + bytes(b ^ mask[i % 4] for i, b in enumerate(data))

    def send(self, text):
        self.s.sendall(self.text_frame(text))

    def close(self):
        self.s.close()
