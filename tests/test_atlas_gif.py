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
    # one palette for the whole animation: all frames together use at most 256 colours
    colours = np.unique(np.concatenate([f.reshape(-1, 3) for f in frames]), axis=0)
    assert len(colours) <= 256
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
