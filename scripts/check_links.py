#!/usr/bin/env python3
"""Checks the book's and the README's links, offline: every relative link and #anchor of the
built book (the HTML that `mdbook build docs` writes) resolves to a file and an element id,
and every relative link of README.md and CHANGELOG.md resolves to a file of the repository
(and a heading, for a #anchor into a Markdown file). Web links are not followed.

Usage: scripts/check_links.py [BOOK_DIR]   (default: target/book); exits 1 listing every
broken link.
"""
import html.parser, os, re, sys, urllib.parse

ROOT = os.path.normpath(os.path.join(os.path.dirname(os.path.abspath(__file__)), '..'))
BOOK = os.path.abspath(sys.argv[1]) if len(sys.argv) > 1 else os.path.join(ROOT, 'target', 'book')
# mdBook's own pages, which hold every chapter or nothing of ours.
SKIP = {'print.html', '404.html', 'toc.html'}


class Page(html.parser.HTMLParser):
    def __init__(self):
        super().__init__()
        self.ids, self.links = set(), []

    def handle_starttag(self, tag, attrs):
        a = dict(attrs)
        if a.get('id'):
            self.ids.add(a['id'])
        if tag == 'a' and a.get('name'):
            self.ids.add(a['name'])
        if tag == 'a' and a.get('href') is not None:
            self.links.append(a['href'])
        if tag == 'img' and a.get('src') is not None:
            self.links.append(a['src'])


def external(link):
    return re.match(r'^[a-z][a-z0-9+.-]*:', link) is not None  # http:, https:, mailto:


CHECKED = [0]


def check_book():
    if not os.path.isfile(os.path.join(BOOK, 'index.html')):
        return [f'{BOOK}: no built book here (run `mdbook build docs` first)']
    pages = {}
    for d, _, files in os.walk(BOOK):
        for f in files:
            if f.endswith('.html'):
                p = Page()
                p.feed(open(os.path.join(d, f), encoding='utf-8').read())
                pages[os.path.normpath(os.path.join(d, f))] = p
    bad = []
    for path, page in sorted(pages.items()):
        if os.path.basename(path) in SKIP:
            continue
        for link in sorted(set(page.links)):
            if external(link) or link == '':
                continue
            CHECKED[0] += 1
            target, _, frag = link.partition('#')
            target = urllib.parse.unquote(target)
            dest = path if target == '' else os.path.normpath(
                os.path.join(os.path.dirname(path), target))
            if os.path.isdir(dest):
                dest = os.path.join(dest, 'index.html')
            where = os.path.relpath(path, BOOK)
            if not os.path.exists(dest):
                bad.append(f'{where}: {link}: no such file in the book')
            elif frag and dest.endswith('.html'):
                ids = pages[dest].ids if dest in pages else set()
                if urllib.parse.unquote(frag) not in ids:
                    bad.append(f'{where}: {link}: no element with id "{frag}" there')
    return bad


def slug(heading):
    """The anchor GitHub (and mdBook) give a heading."""
    h = re.sub(r'`|\*|_(?=\w)|(?<=\w)_', '', heading.strip()).lower()
    h = re.sub(r'\[([^\]]*)\]\([^)]*\)', r'\1', h)
    return re.sub(r'[^\w\- ]', '', h).replace(' ', '-')


def headings(md):
    out, fence = set(), False
    for line in open(md, encoding='utf-8'):
        if line.startswith('```'):
            fence = not fence
        elif not fence and line.startswith('#'):
            out.add(slug(line.lstrip('#')))
    return out


def check_markdown(name):
    path = os.path.join(ROOT, name)
    text = open(path, encoding='utf-8').read()
    text = re.sub(r'```.*?```', '', text, flags=re.S)  # links inside code are not links
    bad = []
    for link in re.findall(r'\]\(([^)\s]+)(?:\s+"[^"]*")?\)', text):
        if external(link):
            continue
        CHECKED[0] += 1
        target, _, frag = link.partition('#')
        dest = path if target == '' else os.path.normpath(
            os.path.join(os.path.dirname(path), urllib.parse.unquote(target)))
        if not os.path.exists(dest):
            bad.append(f'{name}: {link}: no such file in the repository')
        elif frag and dest.endswith('.md') and frag not in headings(dest):
            bad.append(f'{name}: {link}: no heading with anchor "{frag}" there')
    return bad


bad = check_book() + check_markdown('README.md') + check_markdown('CHANGELOG.md')
for b in bad:
    print('broken link:', b, file=sys.stderr)
if bad:
    sys.exit(1)
print(f'links: all {CHECKED[0]} relative links of the book ({os.path.relpath(BOOK, ROOT)}), README.md '
      'and CHANGELOG.md resolve')
