"""The atlas's GIF encoding (:func:`rollingdisk.plotting.animation.writer_for`): one palette
for all frames, each frame's pixels close to what matplotlib drew."""

from __future__ import annotations

import numpy as np
import pytest

from rollingdisk.plotting.animation import write_frames, writer_for


def _scene():
    """A figure whose frames differ (a moving, colour-graded line over a filled field)."""
    from matplotlib.figure import Figure

    fig = Figure(figsize=(2.4, 1.8))
    ax = fig.add_subplot(1, 1, 1)
    x = np.linspace(0.0, 2.0 * np.pi, 200)
    ax.imshow(np.outer(np.linspace(0, 1, 40), np.linspace(0, 1, 60)), cmap="viridis",
              extent=(0, 2 * np.pi, -1.5, 1.5), aspect="auto")
    (line,) = ax.plot(x, np.sin(x), color="tab:red", lw=2.0)

    def draw(i):
        line.set_ydata(np.sin(x + 0.4 * i))

    return fig, draw


def _drawn(fig, draw, i, dpi):
    """Frame ``i`` as matplotlib renders it (RGB, float)."""
    import io

    from PIL import Image

    draw(i)
    buf = io.BytesIO()
    fig.savefig(buf, format="rgba", dpi=dpi)
    w, h = (int(round(v * dpi)) for v in fig.get_size_inches())
    return np.asarray(Image.frombuffer("RGBA", (w, h), buf.getbuffer(), "raw", "RGBA", 0,
                                       1).convert("RGB"), dtype=float)


def _colour_tables(data: bytes) -> tuple[bool, int, int]:
    """Walk a GIF's blocks: (has a global colour table, frames, frames with a local one)."""
    assert data[:6] in (b"GIF87a", b"GIF89a")
    flags = data[10]
    pos = 13 + (3 * 2 ** ((flags & 7) + 1) if flags & 0x80 else 0)
    n = n_local = 0

    def skip_sub_blocks(pos):
        while data[pos]:
            pos += data[pos] + 1
        return pos + 1

    while data[pos] != 0x3B:
        if data[pos] == 0x21:  # extension: label, then sub-blocks
            pos = skip_sub_blocks(pos + 2)
        else:
            assert data[pos] == 0x2C
            f = data[pos + 9]
            n += 1
            pos += 10
            if f & 0x80:
                n_local += 1
                pos += 3 * 2 ** ((f & 7) + 1)
            pos = skip_sub_blocks(pos + 1)  # past the LZW code size
    return bool(flags & 0x80), n, n_local


def test_one_palette_frames_match_the_drawing(tmp_path):
    from PIL import Image

    fig, draw = _scene()
    n, dpi = 12, 60
    out = write_frames(fig, n, draw, tmp_path / "a.gif", writer_for(tmp_path / "a.gif", 10),
                       dpi)
    with Image.open(out) as im:
        assert im.n_frames == n
        assert im.info["duration"] == 100 and im.info["loop"] == 0
        frames = []
        for k in range(n):
            im.seek(k)
            frames.append(np.asarray(im.convert("RGB"), dtype=float))
    # one colour table for the whole animation
    assert _colour_tables(out.read_bytes()) == (True, n, 0)
    for k in (0, n // 2, n - 1):
        err = np.abs(frames[k] - _drawn(fig, draw, k, dpi))
        # a viridis field and an antialiased line need more than 256 colours: each pixel
        # goes to its nearest palette entry; on average within a few levels of 255
        assert err.mean() < 3.0, (k, err.mean())
    assert np.abs(frames[0] - frames[n // 2]).mean() > 0.1  # the frames differ


@pytest.mark.parametrize("suffix", [".GIF", ".gif"])
def test_gif_writer_is_pillows(tmp_path, suffix):
    from matplotlib.animation import PillowWriter

    assert isinstance(writer_for(tmp_path / f"a{suffix}", 5), PillowWriter)
