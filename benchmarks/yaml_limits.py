"""What the YAML limits cost: the bounded loader (nesting depth and alias expansion checked while
composing, in Python over libyaml's events) against libyaml's own composer with the same
location-keeping constructor, on a large generated workflow, in one process on this machine.
Also the sandbox's size checks: evaluating expressions with and without them.

    python benchmarks/yaml_limits.py [--steps 5000] [--repeat 3]
"""
from __future__ import annotations

import argparse
import os
import time

import yaml
from jinja2.sandbox import SandboxedEnvironment

from pipflow.engine import expr, source


class _Unbounded(yaml._yaml.CParser, source._Constructor, yaml.resolver.Resolver):  # type: ignore[name-defined]
    """The loader as it was before the limits: libyaml composes, nothing is counted."""

    def __init__(self, stream: str, file: str):
        yaml._yaml.CParser.__init__(self, stream)
        source._Constructor.__init__(self)
        yaml.resolver.Resolver.__init__(self)
        self.file = file


def _workflow(n: int) -> str:
    steps = "".join(f"  - id: s{i}\n    uses: core.value\n    with: {{value: '${{s{i - 1}.value}}', x: [1, 2, 3]}}\n"
                    for i in range(1, n))
    return "pipflow: 1\nname: big\nsteps:\n  - {id: s0, uses: core.value, with: {value: 0}}\n" + steps


def _best(fn, repeat: int) -> float:
    times = []
    for _ in range(repeat):
        started = time.perf_counter()
        fn()
        times.append(time.perf_counter() - started)
    return min(times)


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--steps", type=int, default=5000)
    parser.add_argument("--repeat", type=int, default=3)
    args = parser.parse_args()
    text = _workflow(args.steps)

    def unbounded() -> None:
        loader = _Unbounded(text, "big.yaml")
        try:
            loader.get_single_data()
        finally:
            loader.dispose()

    bounded = _best(lambda: source.parse_yaml(text, "big.yaml"), args.repeat)
    plain = _best(unbounded, args.repeat)
    print(f"YAML, {len(text) / 1e6:.1f} MB workflow of {args.steps} steps (best of {args.repeat}; "
          f"load average {os.getloadavg()[0]:.1f})")
    print(f"  bounded loader   {bounded:7.3f} s")
    print(f"  libyaml composer {plain:7.3f} s")
    print(f"  ratio            {bounded / plain:7.2f}")

    namespace = {"a": {"value": 3, "text": "abc"}}
    sources = [f"a.value * {i} + 1" for i in range(2000)] + [f"a.text ~ '{i}'" for i in range(2000)]
    checked = _best(lambda: [expr._Expression(s)(**namespace) for s in sources], args.repeat)
    unchecked_env = SandboxedEnvironment()
    unchecked = _best(lambda: [unchecked_env.compile_expression(s)(**namespace) for s in sources], args.repeat)
    print(f"expressions, {len(sources)} compiled and evaluated: size-checked {checked:.3f} s, "
          f"plain sandbox {unchecked:.3f} s, ratio {checked / unchecked:.2f}")


if __name__ == "__main__":
    main()
