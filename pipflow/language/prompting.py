"""Prompt templates: jinja2, sandboxed, strict about undefined variables.

A template file defines the chat messages as blocks named after their roles::

    {% block system %}You write PDDL problems.{% endblock %}
    {% block user %}Command: {{ command }}{% endblock %}

Blocks render in the order ``system``, ``user``, ``assistant`` (those present). A file without
blocks renders as one user message. Strict undefined turns a misspelt variable into an error that
names it instead of an empty string in a prompt nobody reads; the sandbox keeps a template from a
workflow folder from reaching Python internals.
"""
from __future__ import annotations

import os
from pathlib import Path
from typing import Any

from pipflow.errors import InputError

PROMPTS_DIR = Path(__file__).resolve().parent.parent / "prompts"  # installed: pipflow/prompts
_REPO_PROMPTS = Path(__file__).resolve().parents[2] / "prompts"      # a clone: <repo>/prompts
ROLES = ("system", "user", "assistant")


def find_template(name: str, base_dir: Path | None = None) -> Path:
    """A template by path (absolute, or relative to ``base_dir``) or by name in ``prompts/``
    (``warehouse_problem`` or ``warehouse_problem.j2``)."""
    candidates = []
    p = Path(name).expanduser()
    if p.is_absolute():
        candidates.append(p)
    else:
        if base_dir is not None:
            candidates.append(base_dir / p)
        candidates.append(Path.cwd() / p)
        for folder in (PROMPTS_DIR, _REPO_PROMPTS):
            candidates += [folder / p, folder / f"{name}.j2"]
    for c in candidates:
        if c.is_file():
            return c.resolve()
    known = sorted({t.stem for d in (PROMPTS_DIR, _REPO_PROMPTS) if d.is_dir() for t in d.glob("*.j2") if not t.name.startswith("_")})
    raise InputError(f"prompt template {name!r} not found; built-in templates: {', '.join(known) or 'none'}")


def prompt_problem(name: object, base_dir: Path | None = None) -> str | None:
    """The validation check of a ``prompt`` argument: None when the template exists, else why
    (whatever the model, so a misspelt variant fails before anything runs)."""
    if not isinstance(name, str):
        return f"a prompt template name must be text, got {name!r}"
    try:
        find_template(name, base_dir)
    except InputError as err:
        return str(err)
    return None


def _contained_loader(base: type, not_found: type, folders: list[str]):
    """A jinja2 ``FileSystemLoader`` that reads a template or partial (``{% include %}``,
    ``{% extends %}``) only when it really lies in one of its folders: a link among a shared
    template's partials (``header.j2 -> ~/.ssh/id_rsa``) would otherwise put that file into the
    prompt. jinja2 itself refuses ``..`` in names."""

    class Contained(base):  # type: ignore[misc, valid-type]
        def get_source(self, environment, name):  # noqa: ANN001 - jinja2's signature
            source, filename, uptodate = super().get_source(environment, name)
            real = os.path.realpath(filename)
            if not any(real.startswith(os.path.realpath(f).rstrip(os.sep) + os.sep) for f in self.searchpath):
                raise not_found(f"{name} (it leads through a link to {real}, outside the template folders)")
            return source, filename, uptodate

    return Contained(folders)


def render(template: str, variables: dict[str, Any], base_dir: Path | None = None) -> list[dict[str, str]]:
    """Render a template into chat messages ``[{"role", "content"}]``."""
    from jinja2 import FileSystemLoader, StrictUndefined, TemplateError, TemplateNotFound
    from jinja2.sandbox import SandboxedEnvironment

    path = find_template(template, base_dir)
    # the template's own folder first, so a user's variant may import its own partials
    folders = [str(path.parent)] + [str(d) for d in (PROMPTS_DIR, _REPO_PROMPTS) if d.is_dir()]
    env = SandboxedEnvironment(loader=_contained_loader(FileSystemLoader, TemplateNotFound, folders), undefined=StrictUndefined,
                               trim_blocks=True, lstrip_blocks=True, autoescape=False)
    try:
        tmpl = env.get_template(path.name)
        roles = [r for r in ROLES if r in tmpl.blocks]
        if not roles:
            return [{"role": "user", "content": tmpl.render(**variables).strip()}]
        messages = []
        for role in roles:
            ctx = tmpl.new_context(dict(variables))
            content = "".join(tmpl.blocks[role](ctx)).strip()
            if content:
                messages.append({"role": role, "content": content})
        return messages
    except TemplateError as exc:
        line = getattr(exc, "lineno", None)
        where = f"{path}:{line}" if line else str(path)
        raise InputError(f"{where}: prompt template error: {exc}") from None
