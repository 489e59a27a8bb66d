"""The atlas's helper processes (:mod:`rollingdisk.atlas.children`): a helper that dies is
reported by name, never waited for forever."""

from __future__ import annotations

import multiprocessing
import os

import pytest

from rollingdisk.atlas.steps import _collect_to_rest


def _die(conn):
    os._exit(3)  # no record sent


def _send(conn):
    conn.send({"gif": False, "n_impacts": 7})
    conn.close()


def _start(target):
    receive, send = multiprocessing.Pipe(duplex=False)
    proc = multiprocessing.Process(target=target, args=(send,), daemon=True)
    proc.start()
    send.close()
    return proc, receive


def test_a_dead_run_to_rest_helper_is_an_error(tmp_path):
    with pytest.raises(RuntimeError, match="run-to-rest process ended with exit code 3"):
        _collect_to_rest(_start(_die), tmp_path, True, [])


def test_the_run_to_rest_record_comes_back(tmp_path):
    files = []
    assert _collect_to_rest(_start(_send), tmp_path, True, files) == {"gif": False,
                                                                       "n_impacts": 7}
    assert files == []  # no GIF when the record says so
