"""C streams (FILE *) for the harness calls that read or write one, made by the C library
(glibc): open_memstream collects what a call writes, fmemopen lends it bytes to read."""

import ctypes
import ctypes.util
import contextlib

from ._errors import HandspringError

_libc = ctypes.CDLL(ctypes.util.find_library("c") or "libc.so.6", use_errno=True)
_libc.open_memstream.restype = ctypes.c_void_p
_libc.open_memstream.argtypes = [ctypes.POINTER(ctypes.c_void_p), ctypes.POINTER(ctypes.c_size_t)]
_libc.fmemopen.restype = ctypes.c_void_p
_libc.fmemopen.argtypes = [ctypes.c_void_p, ctypes.c_size_t, ctypes.c_char_p]
_libc.fopen.restype = ctypes.c_void_p
_libc.fopen.argtypes = [ctypes.c_char_p, ctypes.c_char_p]
_libc.fclose.argtypes = [ctypes.c_void_p]
_libc.free.argtypes = [ctypes.c_void_p]


class _Sink:
    data = b""


@contextlib.contextmanager
def writer():
    """`with writer() as (stream, sink)`: after the block, sink.data holds what was written."""
    buf, size = ctypes.c_void_p(), ctypes.c_size_t()
    stream = _libc.open_memstream(ctypes.byref(buf), ctypes.byref(size))
    if not stream:
        raise HandspringError("open_memstream failed: errno %d" % ctypes.get_errno())
    sink = _Sink()
    try:
        yield stream, sink
    finally:
        _libc.fclose(stream)  # flushes: buf and size are final only now
        sink.data = ctypes.string_at(buf, size.value) if buf.value else b""
        _libc.free(buf)


@contextlib.contextmanager
def reader(data):
    """`with reader(data) as stream`: a read-only stream over the bytes."""
    data = bytes(data)
    buf = ctypes.create_string_buffer(data, max(len(data), 1))
    # fmemopen refuses a size of 0: no bytes read as an empty file does
    stream = _libc.fmemopen(buf, len(data), b"rb") if data else _libc.fopen(b"/dev/null", b"rb")
    if not stream:
        raise HandspringError("fmemopen failed: errno %d" % ctypes.get_errno())
    try:
        yield stream
    finally:
        _libc.fclose(stream)
