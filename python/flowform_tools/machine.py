"""Machine, commit and binary information printed with benchmark results."""
import datetime
import os
import platform
import re
import subprocess

from . import REPO


def machine_info(repo=REPO):
    """platform, date (UTC), CPU model and count, memory, and the work tree's commit."""
    info = {"platform": platform.platform(), "date": datetime.datetime.now(datetime.timezone.utc)
            .strftime("%Y-%m-%d %H:%M UTC")}
    try:
        out = subprocess.run(["lscpu"], stdout=subprocess.PIPE, text=True).stdout
        for key in ("Model name", "CPU(s)"):
            m = re.search(rf"^{re.escape(key)}:\s*(.+)$", out, re.M)
            if m:
                info[key] = m.group(1).strip()
    except OSError:
        pass
    try:
        with open("/proc/meminfo") as f:
            kb = int(re.search(r"MemTotal:\s+(\d+)", f.read()).group(1))
        info["memory"] = f"{kb / 2**20:.1f} GiB"
    except (OSError, AttributeError):
        pass
    try:
        info["commit"] = subprocess.run(["git", "-C", repo, "rev-parse", "--short", "HEAD"],
                                        stdout=subprocess.PIPE, text=True).stdout.strip()
        dirty = subprocess.run(["git", "-C", repo, "status", "--porcelain", "--untracked-files=no"],
                               stdout=subprocess.PIPE, text=True).stdout.strip()
        if dirty:
            info["commit"] += " (work tree modified)"
    except OSError:
        pass
    return info


def binary_built(path, seconds=False):
    """The executable's modification time (UTC): a rebuild during a benchmark shows up."""
    built = datetime.datetime.fromtimestamp(os.path.getmtime(path), datetime.timezone.utc)
    return built.strftime("%Y-%m-%d %H:%M:%S UTC" if seconds else "%Y-%m-%d %H:%M UTC")


def load():
    """The 1-minute load average (about 1.0 = one busy process)."""
    return os.getloadavg()[0]


def uptime():
    return subprocess.run(["uptime"], stdout=subprocess.PIPE, text=True).stdout.strip()
