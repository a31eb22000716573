"""Relative links in the user documentation resolve: every `[text](target)` of README.md, TESTING.md
and docs/*.md whose target is not a URL names a file or folder of the repository, and a `#anchor`
names a heading of the file it points to (GitHub's anchor rule: lower case, punctuation but
`-` and `_` dropped, spaces to `-`). The README also stays a landing page: at most 300 lines and
25,000 characters."""
import glob
import os
import re
import unittest

REPO = os.path.realpath(os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", ".."))
LINK = re.compile(r"\[[^\]]*\]\(([^)\s]+)(?:\s+\"[^\"]*\")?\)")
FENCE = re.compile(r"^```.*?^```", re.M | re.S)


def documents():
    names = ["README.md", "TESTING.md"] + sorted(glob.glob(os.path.join(REPO, "docs", "*.md")))
    return [os.path.join(REPO, n) for n in names]


def anchors(path):
    """GitHub's anchors of the headings of the Markdown file `path`."""
    seen, out = {}, set()
    with open(path, encoding="utf-8") as f:
        text = FENCE.sub("", f.read())
    for line in text.splitlines():
        m = re.match(r"^#{1,6}\s+(.*?)\s*#*\s*$", line)
        if not m:
            continue
        slug = re.sub(r"[^\w\- ]", "", m.group(1).strip().lower()).replace(" ", "-")
        count = seen.get(slug, 0)
        seen[slug] = count + 1
        out.add(slug if count == 0 else "%s-%d" % (slug, count))
    return out


def broken_links(path):
    """(line number, target, why) of each relative link of `path` that does not resolve."""
    broken = []
    with open(path, encoding="utf-8") as f:
        text = f.read()
    text = FENCE.sub(lambda m: "\n" * m.group(0).count("\n"), text)  # code is not linked
    for number, line in enumerate(text.splitlines(), 1):
        for target in LINK.findall(line):
            if re.match(r"^[a-z][a-z0-9+.-]*:", target):  # http:, https:, mailto:
                continue
            file_part, _, anchor = target.partition("#")
            linked = path if not file_part else os.path.normpath(
                os.path.join(os.path.dirname(path), file_part))
            if not linked.startswith(REPO + os.sep) or not os.path.exists(linked):
                broken.append((number, target, "no such file in the repository"))
            elif anchor and linked.endswith(".md") and anchor not in anchors(linked):
                broken.append((number, target, "no heading with that anchor"))
    return broken


class DocumentationLinks(unittest.TestCase):
    def test_relative_links_resolve(self):
        problems = ["%s:%d: %s (%s)" % (os.path.relpath(p, REPO), n, t, why)
                    for p in documents() for n, t, why in broken_links(p)]
        self.assertEqual(problems, [], "\n".join(problems))

    def test_readme_is_a_landing_page(self):
        with open(os.path.join(REPO, "README.md"), encoding="utf-8") as f:
            text = f.read()
        self.assertLessEqual(len(text.splitlines()), 300)
        self.assertLessEqual(len(text), 25000)

    def test_every_docs_page_is_reachable_from_the_readme(self):
        with open(os.path.join(REPO, "README.md"), encoding="utf-8") as f:
            linked = {os.path.normpath(os.path.join(REPO, t.partition("#")[0]))
                      for t in LINK.findall(f.read())}
        pages = glob.glob(os.path.join(REPO, "docs", "*.md")) + [os.path.join(REPO, "TESTING.md"),
                                                                  os.path.join(REPO, "BENCHMARKS.md")]
        missing = [os.path.relpath(p, REPO) for p in pages if os.path.normpath(p) not in linked]
        self.assertEqual(missing, [], "pages the README does not link: %s" % missing)


if __name__ == "__main__":
    unittest.main()
