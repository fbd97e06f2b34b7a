#!/usr/bin/env python3
"""Writes the book's architecture page's generated parts (docs/architecture.md, between the
`<!-- crate_graph.py ... -->` markers): the crate graph, from `cargo metadata` (the workspace
and the Python package), and the module map, from each module's first `//!` line.

Usage: scripts/crate_graph.py          rewrite the page
       scripts/crate_graph.py --check  exit 1 if the page is not what the tree gives (the test
                                       command runs this)
"""
import json, os, re, subprocess, sys

ROOT = os.path.normpath(os.path.join(os.path.dirname(os.path.abspath(__file__)), '..'))
PAGE = os.path.join(ROOT, 'docs', 'architecture.md')


def metadata(manifest):
    out = subprocess.run(['cargo', 'metadata', '--format-version', '1', '--no-deps', '--offline',
                          '--manifest-path', os.path.join(ROOT, manifest)],
                         check=True, capture_output=True, text=True).stdout
    return json.loads(out)['packages']


def crates():
    """(name, folder, workspace deps, other normal deps) of every crate, the CLI and Python."""
    pkgs = metadata('Cargo.toml') + metadata('python/Cargo.toml')
    out = {}
    for p in pkgs:
        folder = os.path.relpath(os.path.dirname(p['manifest_path']), ROOT)
        folder = 'src/' if folder == '.' else folder + '/'
        normal = [d for d in p['dependencies'] if d['kind'] is None]
        local = sorted(d['name'] for d in normal if d.get('path'))
        other = sorted(d['name'] for d in normal if not d.get('path'))
        out[p['name']] = (folder, local, other)
    return out


def level(name, cs, memo={}):
    if name not in memo:
        memo[name] = 1 + max((level(d, cs) for d in cs[name][1]), default=-1)
    return memo[name]


def graph():
    cs = crates()
    short = lambda n: n.replace('snooker-', '') if n != 'snooker' else n
    rows = sorted(cs, key=lambda n: (-level(n, cs), n))
    w = max(len(f'{n} ({cs[n][0]})') for n in cs)
    lines = ['```text', 'level  crate (folder)' + ' ' * (w - 14) + '  uses (workspace crates)']
    last = None
    for n in rows:
        lv = level(n, cs)
        head = f'{lv:>5}  ' if lv != last else ' ' * 7
        last = lv
        uses = ', '.join(short(d) for d in cs[n][1]) or '-'
        lines.append(f'{head}{n + " (" + cs[n][0] + ")":<{w}}  -> {uses}')
    lines.append('```')
    lines.append('')
    lines.append('Each crate\'s other dependencies (normal ones; dev-dependencies left out):')
    lines.append('')
    lines.append('| crate | other dependencies |')
    lines.append('|---|---|')
    for n in rows:
        lines.append(f'| `{n}` | {", ".join("`" + d + "`" for d in cs[n][2]) or "none"} |')
    return '\n'.join(lines)


def modules():
    cs = crates()
    lines = []
    for n in sorted(cs, key=lambda n: (level(n, cs), n)):
        src = os.path.join(ROOT, cs[n][0] if cs[n][0] == 'src/' else cs[n][0] + 'src')
        lines.append(f'### `{n}` (`{os.path.relpath(src, ROOT)}/`)')
        lines.append('')
        lines.append('| module | what it holds |')
        lines.append('|---|---|')
        paths = []
        for dirpath, dirs, files in os.walk(src):
            dirs.sort()
            paths += [os.path.join(dirpath, f) for f in files if f.endswith('.rs')]
        for path in sorted(paths, key=lambda p: os.path.relpath(p, src)):
            text = open(path, encoding='utf-8').read().splitlines()
            doc = []
            for l in text:
                if l.startswith('//!'):
                    doc.append(l[3:].strip())
                elif doc:
                    break
            # The first sentence (or the first line when it runs on).
            joined = ' '.join(doc)
            cut = joined.find('. ')
            first = joined if cut < 0 else joined[:cut + 1]
            # rustdoc's intra-doc links ([`Name`], [`Name`](path)) read as plain code here.
            first = re.sub(r'\[(`[^`]*`)\](\([^)]*\))?', r'\1', first)
            first = first.replace('|', '\\|')
            lines.append(f'| `{os.path.relpath(path, ROOT)}` | {first} |')
        lines.append('')
    return '\n'.join(lines).rstrip()


def splice(text, key, body):
    a, b = f'<!-- crate_graph.py: {key} -->', f'<!-- crate_graph.py: end of {key} -->'
    i, j = text.index(a) + len(a), text.index(b)
    return text[:i] + '\n' + body + '\n' + text[j:]


def main():
    old = open(PAGE, encoding='utf-8').read()
    new = splice(splice(old, 'graph', graph()), 'modules', modules())
    if '--check' in sys.argv:
        if new != old:
            sys.exit('docs/architecture.md is not what the tree gives (a crate, a dependency or a '
                     "module's first doc line changed): run scripts/crate_graph.py")
        return
    open(PAGE, 'w', encoding='utf-8').write(new)


main()
