#!/usr/bin/python3
"""An independent CANopen SDO client for volcomp, written from the CiA 301 frame layouts (not from
volcomp's C++ code), on Debian's python3-can 4.1.0 over SLCAN.

It uploads a table image to a node by SDO block download (CRC-16/XMODEM = binascii.crc_hqx), has
the node verify it, reads the staged CRC-32 back and compares it with zlib.crc32 of the image,
references the axes, activates the table and checks the active CRC-32. Then the transmit PDOs,
from the CiA 301 frame layout and the documented mapping (docs/canopen.md, "PDOs"): NMT start,
TPDO1 (0x180 + node-ID: device state U16, clamped axes U8, rate-limited axes U8, corrections of
axes 1-2 as I16 steps) and TPDO2 (0x280 + node-ID: axes 3-6) decoded and compared with SDO reads of
0x2122, 0x2125, 0x2126 and 0x2131 (q8), the event timer changed by SDO and its rate counted, TPDO2
disabled by bit 31 of its COB-ID and enabled again. Then the receive PDO (0x200 + node-ID, the
command word 0x2127, U16, bits acting on their rising edge): ignored in pre-operational;
deactivate (bit 8) drops the active table; activate (bit 9) with nothing staged is refused with
EMCY 0xFF10 carrying abort 0x08000024; a one-byte frame gives EMCY 0x8210. Exit code 0 on success.

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


def collect(bus, seconds):
    """Every frame received during `seconds`: (arrival time, CAN-ID, data)."""
    out, end = [], time.monotonic() + seconds
    while time.monotonic() < end:
        msg = bus.recv(max(0.0, end - time.monotonic()))
        if msg is not None and not msg.is_extended_id:
            out.append((time.monotonic(), msg.arbitration_id, bytes(msg.data)))
    return out


def signed32(v):
    return v - (1 << 32) if v & 0x80000000 else v


def steps_of_q8(q8):
    """0x2131 (q8 steps) rounded half away from zero, saturated at +-32767 (the TPDO form)."""
    steps = int((abs(q8) + 128) // 256) * (1 if q8 >= 0 else -1)
    return max(-32767, min(32767, steps))


def check_pdos(c, bus, node):
    tpdo1, tpdo2 = 0x180 + node, 0x280 + node
    assert c.read(0x1800, 1) == tpdo1, "TPDO1 COB-ID"
    assert c.read(0x1801, 1) == tpdo2, "TPDO2 COB-ID"
    before = collect(bus, 0.5)  # pre-operational: no PDO
    assert not [f for f in before if f[1] in (tpdo1, tpdo2)], "a PDO before NMT start"
    bus.send(can.Message(arbitration_id=0x000, data=bytes([0x01, node]), is_extended_id=False))
    for attempt in range(5):  # the values could change between the frame and the reads
        frames = collect(bus, 1.0)
        f1 = [f for f in frames if f[1] == tpdo1]
        f2 = [f for f in frames if f[1] == tpdo2]
        assert f1 and f2, "no TPDO in operational (%d frames seen)" % len(frames)
        assert len(f1[-1][2]) == 8 and len(f2[-1][2]) == 8, "TPDO length"
        state, clamped, limited, c1, c2 = struct.unpack("<HBBhh", f1[-1][2])
        rest = struct.unpack("<hhhh", f2[-1][2])
        sdo_state = c.read(0x2122, 0)
        sdo_clamped, sdo_limited = c.read(0x2125, 0), c.read(0x2126, 0)
        sdo = [steps_of_q8(signed32(c.read(0x2131, a))) for a in range(1, 7)]
        if (state, clamped, limited, [c1, c2] + list(rest)) == (sdo_state, sdo_clamped,
                                                                 sdo_limited, sdo):
            break
    else:
        raise AssertionError("TPDO %04X %02X %02X %s differ from SDO %04X %02X %02X %s"
                             % (state, clamped, limited, [c1, c2] + list(rest), sdo_state,
                                sdo_clamped, sdo_limited, sdo))
    print("TPDO1 state 0x%04X clamped 0x%02X limited 0x%02X corrections %s steps: as SDO reads"
          % (state, clamped, limited, [c1, c2] + list(rest)))
    # At rest only the event timer sends: 100 ms by default; 50 ms by SDO (writable while the PDO
    # exists) doubles the rate. Generous bounds: the machine may be loaded.
    window = 3.0
    n100 = len([f for f in collect(bus, window) if f[1] == tpdo1])
    c.write(0x1800, 5, 50, size=2)
    n50 = len([f for f in collect(bus, window) if f[1] == tpdo1])
    c.write(0x1800, 5, 100, size=2)
    print("TPDO1 frames in %.0f s: %d with the 100 ms event timer, %d with 50 ms"
          % (window, n100, n50))
    assert 15 <= n100 <= window * 1000 / 100 + 5, "100 ms event timer: %d frames" % n100
    assert n50 >= 1.4 * n100 and n50 <= window * 1000 / 50 + 5, "50 ms event timer: %d" % n50
    # Bit 31 of the COB-ID: TPDO2 does not exist, no frame; cleared: back at once.
    c.write(0x1801, 1, tpdo2 | 0x80000000)
    collect(bus, 0.1)
    off = [f for f in collect(bus, 0.6) if f[1] == tpdo2]
    assert not off, "TPDO2 sent while its COB-ID says it does not exist"
    c.write(0x1801, 1, tpdo2)
    on = [f for f in collect(bus, 0.6) if f[1] == tpdo2]
    assert on, "TPDO2 not back after clearing bit 31"
    print("TPDO2 disabled by bit 31 (no frame in 0.6 s), enabled again (%d frames)" % len(on))
    bus.send(can.Message(arbitration_id=0x000, data=bytes([0x80, node]), is_extended_id=False))


def emcys(frames, node):
    """The EMCYs among `frames` other than "error reset": (code, manufacturer bytes 3-7)."""
    out = []
    for _, cob, data in frames:
        if cob == 0x80 + node and len(data) == 8:
            code = struct.unpack_from("<H", data)[0]
            if code != 0:
                out.append((code, data[3:]))
    return out


def check_rpdo(c, bus, node):
    rpdo = 0x200 + node
    assert c.read(0x1400, 1) == rpdo, "RPDO1 COB-ID"
    assert c.read(0x1600, 1) == 0x21270010, "RPDO1 mapping: 0x2127:0, 16 bits"

    def send(word, dlc=2):
        bus.send(can.Message(arbitration_id=rpdo, data=struct.pack("<H", word)[:dlc],
                             is_extended_id=False))
        return emcys(collect(bus, 0.3), node)

    active = c.read(0x2104, 0)
    assert active != 0, "no active table before the RPDO checks"
    assert not send(0x0100), "an EMCY for an RPDO in pre-operational"
    assert c.read(0x2104, 0) == active, "an RPDO acted in pre-operational"
    bus.send(can.Message(arbitration_id=0x000, data=bytes([0x01, node]), is_extended_id=False))
    time.sleep(0.1)
    e = send(0x0100)  # deactivate rises
    assert not e, "deactivation by RPDO refused: %s" % e
    assert c.read(0x2104, 0) == 0, "the table is still active after the RPDO's deactivate"
    assert c.read(0x2127, 0) == 0x0100, "0x2127 does not read the word taken"
    e = send(0x0200)  # activate rises, nothing staged (the activation took it)
    assert (0xFF10, struct.pack("<I", 0x08000024) + b"\0") in e, \
        "no EMCY 0xFF10 with 0x08000024 for a refused activation: %s" % e
    e = send(0x0000, dlc=1)
    assert [x for x in e if x[0] == 0x8210], "no EMCY 0x8210 for a 1-byte RPDO: %s" % e
    print("RPDO: deactivate acted, refused activate gave EMCY 0xFF10 0x08000024, short frame 0x8210")
    bus.send(can.Message(arbitration_id=0x000, data=bytes([0x80, node]), is_extended_id=False))


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
        check_pdos(c, bus, a.node)
        check_rpdo(c, bus, a.node)
        print("independent client: OK")
        return 0
    finally:
        bus.shutdown()


if __name__ == "__main__":
    sys.exit(main())
