"""Running commands as a user types them: in a login shell with nothing sourced.

The README's commands must work from a plain shell (no OpenFOAM, no
ldnaFoam environment, a minimal PATH) and from one where an OpenFOAM
environment is already sourced.  These helpers run a command line in such a
clean environment with ``env -i``, from a given directory, and return its exit
code and output.
"""
from __future__ import annotations

import os
import subprocess
from dataclasses import dataclass
from pathlib import Path

from ldna.case import PROJECT_DIR

#: The OpenFOAM environment bin/ldna-install writes (a sourced OpenFOAM)
OPENFOAM_ENV = PROJECT_DIR / "build" / "openfoam-env.sh"

#: Shells a user may type the commands in: nothing sourced, or OpenFOAM sourced
SHELLS = {
    "plain": "",
    "openfoam-sourced": f'. "{OPENFOAM_ENV}" && ',
}


@dataclass
class Outcome:
    """Exit code and combined output of a command line."""

    returncode: int
    output: str


def clean_env(**extra: str) -> dict[str, str]:
    """The environment of a fresh login shell: HOME, a minimal PATH, nothing else."""
    env = {"HOME": os.environ.get("HOME", "/root"), "PATH": "/usr/bin:/bin"}
    env.update(extra)
    return env


def user_command(command: str, shell: str = "plain", **extra_env: str) -> list[str]:
    """The argument list that runs ``command`` with bash in a clean environment."""
    return ["env", "-i", *(f"{k}={v}" for k, v in clean_env(**extra_env).items()),
            "bash", "-c", SHELLS[shell] + command]


def run_as_user(command: str, cwd: Path = PROJECT_DIR, shell: str = "plain",
                timeout: float = 1800, **extra_env: str) -> Outcome:
    """Run ``command`` with bash in a clean environment from ``cwd``.

    ``shell`` is a key of :data:`SHELLS`: what the user has sourced before.
    """
    proc = subprocess.run(user_command(command, shell, **extra_env), cwd=cwd,
                          capture_output=True, text=True, timeout=timeout, check=False)
    return Outcome(proc.returncode, proc.stdout + proc.stderr)
