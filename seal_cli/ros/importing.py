"""A bag's run as an observations file (``seal import-bag``), for ``seal localize --observations``.

The file is the one :func:`seal_cli.sensing.observations.read_observations` reads: one entry per
detection message, its pose ``[x, y, yaw]`` and detections ``{class, at}`` in the map frame, with
the message's stamp and the bag's position as a comment (the format has no key for them)::

    # seal import-bag run.mcap: 200 detection messages on /detections, poses from /tf, frame map
    observations:
      - pose: [-5.95, -3.0, 0.05]   # t = 10.250 s, /detections message 1
        detections:
          - {class: spoon, at: [7.0, -5.0]}
"""

from __future__ import annotations

from seal_cli.ros.bags import Run

__all__ = ["observations_text"]


def _number(v: float) -> str:
    """The shortest text that reads back as the same float: the file gives the same beliefs as the bag."""
    return repr(float(v))


def observations_text(run: Run, source: str, frame: str) -> str:
    """The YAML text of an observations file holding the run."""
    lines = [_comment(f"# seal import-bag {source}: {len(run.observations)} detection messages on "
                      f"{run.detections_topic}, poses from {run.pose_source}, frame {frame}"), "observations:"]
    for obs, stamp in zip(run.observations, run.stamps, strict=True):
        where = str(obs.where).rsplit(" ", 3)
        place = " ".join(where[-3:]) if len(where) == 4 else ""
        pose = ", ".join(_number(v) for v in obs.pose)
        lines.append(_comment(f"  - pose: [{pose}]   # t = {stamp:.3f} s, {place}".rstrip(", ")))
        if not obs.detections:
            lines.append("    detections: []")
            continue
        lines.append("    detections:")
        for cls, (x, y) in obs.detections:
            lines.append(f"      - {{class: {_quoted(cls)}, at: [{_number(x)}, {_number(y)}]}}")
    return "\n".join(lines) + "\n"


def _comment(line: str) -> str:
    """One line of the file, its comment's characters that would end the line (a newline or YAML's other line
    breaks, U+0085, U+2028, U+2029) or that YAML refuses written as escapes: a bag called ``r\\nx: [.mcap``, or a
    topic so named, made the comment's rest a line of YAML, and the file seal wrote could not be read back."""
    return "".join(c if c.isprintable() else c.encode("unicode_escape").decode("ascii") for c in line)


def _quoted(name: str) -> str:
    """A class name as a YAML scalar that reads back as the same string."""
    import yaml

    text = yaml.safe_dump(name, default_flow_style=True).strip()
    return text.removesuffix("\n...").removesuffix("...").strip()
