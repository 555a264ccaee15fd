#!/usr/bin/python3
"""An independent CANopen SDO client for volcomp, written from the CiA 301 frame layouts (not from
volcomp's C++ code), on Debian's python3-can 4.1.0 over SLCAN.

It uploads a table image to a node by SDO block download (CRC-16/XMODEM = binascii.crc_hqx), has
the node verify it, reads the staged CRC-32 back and compares it with zlib.crc32 of the image,
references the axes, activates the table and checks the active CRC-32. Exit code 0 on success.

usage: independent_sdo_client.py CHANNEL IMAGE [--node 16]
  CHANNEL: socket://HOST:PORT (SLCAN over TCP) or a serial/pty path (SLCAN over a tty)
"""
import argparse
import binascii
import struct
import sys
import time
import zlib

import can  # python3-can

ABORTS = {
    0x05040000: "SDO protocol timed out", 0x06010002: "attempt to write a read-only object",
    0x06020000: "object does not exist", 0x08000020: "cannot be stored (write-protected)",
    0x08000022: "not allowed in the present device state", 0x05040004: "CRC error",
}


class SdoError(Exception):
    def __init__(self, code, what):
        super().__init__("%s: abort 0x%08X (%s)" % (what, code, ABORTS.get(code, "?")))
        self.code = code


class Client:
    def __init__(self, bus, node, timeout=1.0):
        self.bus, self.node, self.timeout = bus, node, timeout
        self.rx_id, self.tx_id = 0x600 + node, 0x580 + node

    def send(self, data):
        self.bus.send(can.Message(arbitration_id=self.rx_id, data=bytes(data).ljust(8, b"\0"),
                                  is_extended_id=False))

    def recv(self, what):
        end = time.monotonic() + self.timeout
        while time.monotonic() < end:
            msg = self.bus.recv(max(0.0, end - time.monotonic()))
            if msg is None or msg.arbitration_id != self.tx_id or msg.dlc != 8:
                continue
            data = bytes(msg.data)
            if data[0] == 0x80:
                raise SdoError(struct.unpack_from("<I", data, 4)[0], what)
            return data
        raise TimeoutError("no SDO response for " + what)

    # -- expedited transfers (CiA 301 7.2.4.3.3 / 7.2.4.3.6) --
    def read(self, index, sub):
        self.send(struct.pack("<BHB", 0x40, index, sub))
        r = self.recv("read %04X:%02X" % (index, sub))
        if (r[0] & 0xE3) != 0x43:
            raise RuntimeError("expected an expedited upload response, got %02X" % r[0])
        n = 4 - ((r[0] >> 2) & 3)
        return int.from_bytes(r[4:4 + n], "little")

    def write(self, index, sub, value, size=4):
        cmd = 0x23 | ((4 - size) << 2)
        self.send(struct.pack("<BHB", cmd, index, sub) + value.to_bytes(size, "little"))
        r = self.recv("write %04X:%02X" % (index, sub))
        if r[0] != 0x60:
            raise RuntimeError("expected a download response, got %02X" % r[0])

    # -- block download (CiA 301 7.2.4.3.9 - 7.2.4.3.14) --
    def block_download(self, index, sub, payload):
        self.send(struct.pack("<BHBI", 0xC6, index, sub, len(payload)))  # CRC + size indicated
        r = self.recv("block download initiate")
        if (r[0] & 0xFB) != 0xA0:
            raise RuntimeError("unexpected initiate response %02X" % r[0])
        blksize = r[4]
        pos, resent = 0, 0
        while pos < len(payload):
            seq, start = 0, pos
            while seq < blksize and start + seq * 7 < len(payload):
                chunk = payload[start + seq * 7:start + seq * 7 + 7]
                seq += 1
                last = start + seq * 7 >= len(payload)
                self.send(bytes([seq | (0x80 if last else 0)]) + chunk)
            r = self.recv("sub-block acknowledgement")
            if r[0] != 0xA2:
                raise RuntimeError("expected a block ack, got %02X" % r[0])
            ackseq, blksize = r[1], r[2]
            resent += seq - ackseq
            pos = min(len(payload), start + ackseq * 7)
        unused = (7 - len(payload) % 7) % 7
        crc = binascii.crc_hqx(payload, 0)
        self.send(struct.pack("<BH", 0xC1 | (unused << 2), crc))
        r = self.recv("block download end")
        if r[0] != 0xA1:
            raise RuntimeError("expected the end response, got %02X" % r[0])
        return resent


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("channel")
    ap.add_argument("image")
    ap.add_argument("--node", type=int, default=16)
    a = ap.parse_args()
    image = open(a.image, "rb").read()
    expected_crc = zlib.crc32(image[:-4]) & 0xFFFFFFFF
    assert struct.unpack_from("<I", image, len(image) - 4)[0] == expected_crc, "image trailer"
    bus = can.Bus(interface="slcan", channel=a.channel, bitrate=1000000, sleep_after_open=0)
    try:
        c = Client(bus, a.node)
        vendor = c.read(0x1018, 1)
        print("vendor id 0x%08X" % vendor)
        try:  # a refused write must come back as an abort with the CiA code
            c.write(0x1000, 0, 1)
            raise RuntimeError("writing the read-only 0x1000 was accepted")
        except SdoError as e:
            assert e.code == 0x06010002, e
            print("read-only write refused as expected:", e)
        c.write(0x2110, 0, 0x6B6C6E75)          # unlock ("unlk")
        c.write(0x2101, 0, 3, size=1)           # clear the staging bank
        t0 = time.monotonic()
        resent = c.block_download(0x2100, 0, image)
        dt = time.monotonic() - t0
        print("block download: %d bytes in %.2f s (%.1f kB/s), %d segments resent"
              % (len(image), dt, len(image) / dt / 1000, resent))
        c.write(0x2101, 0, 4, size=1)           # verify
        staged = c.read(0x2105, 0)
        print("staged CRC-32 0x%08X, expected 0x%08X" % (staged, expected_crc))
        assert staged == expected_crc, "staged CRC-32 differs"
        try:  # not referenced yet: activation must be refused with 0x08000022
            c.write(0x2101, 0, 1, size=1)
            raise RuntimeError("activation before referencing was accepted")
        except SdoError as e:
            assert e.code == 0x08000022, e
            print("activation before referencing refused as expected")
        c.write(0x2120, 0, 0x07, size=1)        # reference axes 1..3
        time.sleep(0.3)                         # at rest for the node's 100 ms
        c.write(0x2101, 0, 1, size=1)           # activate
        active = c.read(0x2104, 0)
        print("active CRC-32 0x%08X" % active)
        assert active == expected_crc, "active CRC-32 differs"
        print("independent client: OK")
        return 0
    finally:
        bus.shutdown()


if __name__ == "__main__":
    sys.exit(main())
