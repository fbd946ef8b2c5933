#!/usr/bin/env python3
"""No dangling doc reference (issue 39): code, scripts, tests and docs cite documentation by
file and section, and this test fails when a citation points at nothing.

Checked, in every source, script, CMake and Markdown file of the tree (build trees, .git
and hidden folders left out):

1. every mention of a `*.md` path names a file that exists (relative to the repository
   root or to the mentioning file's folder; a bare name may be anywhere in the tree);
2. every section citation - `docs/player/streaming.md "Streaming"`, `formats/README.md
   "LGHT", "MEXT"`, `README "Install"`, `README, *Install*`, optionally followed by
   `, step N` - names a heading (or a bold paragraph lead such as `**Validation.**`) of
   that file; a title may stop where the heading goes on after a non-letter (`"Compression"`
   matches `#### Compression (format 2)`), and `step N` needs an item `N.` in that section.
   A bare README is the root README.md. A "README step N" with no section is refused: the
   README is not a manual any more, cite the docs file;
3. every relative Markdown link and image in a `.md` file resolves, and a `#anchor` on a
   Markdown target is one of its headings (GitHub's slugs: lower case, punctuation but `-`
   and `_` dropped, spaces to `-`, repeats numbered).

Paths in tests/docs/doc_references_allowlist.txt may dangle (documents landing from another
branch); the test says when an allowed path exists, so the entry can go.

    check_doc_references.py SOURCE_DIR
"""
import os
import re
import sys

SOURCE_EXT = {".cpp", ".h", ".hpp", ".c", ".cc", ".glsl", ".comp", ".geom", ".vert", ".frag",
              ".py", ".sh", ".cmake", ".txt", ".md", ".in", ".json"}
SOURCE_NAMES = {"CMakeLists.txt", "run"}
SKIP_DIRS = {".git", "node_modules", "__pycache__"}

# A path ending in .md, not part of a longer token ($out/table.md, x.md.tmp, PREFIX/...).
MD_PATH = re.compile(r"(?<![\w$/.{}@%*<-])((?:\.\.?/)*(?:[\w.-]+/)*[\w-][\w.-]*\.md)(?![\w.])")
# FILE "Section"[, "Section"...][, step N]   or   FILE, *Section*
QUOTED = r'\\?"[^"\n]{1,120}?\\?"'          # also \"...\" inside a shell string
SECTION_REF = re.compile(
    r'(?P<file>(?<![\w./-])(?:(?:\.\.?/)*(?:[\w.-]+/)*[\w-][\w.-]*\.md|README)(?![\w.]))'
    r'(?:,?[ \t]+\(?(?P<secs>' + QUOTED + r'(?:[ \t]*(?:,|and)[ \t]*' + QUOTED + r')*)'
    r'|,?[ \t]+\*(?P<ital>[^*\n]{1,120})\*)'
    r'(?P<step>,?[ \t]+step[ \t]+(?P<n>\d+))?')
BARE_STEP = re.compile(r'(?<![\w./-])README(?:\.md)?[ \t]+step[ \t]+\d+')
# Another project's README ("the extension's README, "glTF Schema Updates"").
FOREIGN = re.compile(r"(?:its|extension's|extensions'|their)[ \t]+$")
MD_LINK = re.compile(r"(!?)\[((?:[^\[\]]|\[[^\]]*\])*)\]\(<?([^)\s>]+)>?(?:[ \t]+\"[^\"]*\")?\)")
HEADING = re.compile(r"^(#{1,6})[ \t]+(.+?)[ \t]*#*[ \t]*$")
BOLD_LEAD = re.compile(r"^[ \t]*(?:[*-][ \t]+|\d+\.[ \t]+)?\*\*(.+?)\*\*")


def walk(root):
    for dirpath, dirnames, filenames in os.walk(root):
        rel = os.path.relpath(dirpath, root)
        dirnames[:] = sorted(d for d in dirnames
                             if d not in SKIP_DIRS and not (d.startswith(".") and d != ".ci")
                             and not (rel == "." and (d.startswith("build") or d == "out" or d == "shared")))
        for name in sorted(filenames):
            ext = os.path.splitext(name)[1]
            if ext in SOURCE_EXT or name in SOURCE_NAMES:
                path = os.path.join(dirpath, name)
                if name == "run" and not rel.endswith(".ci"):
                    continue
                yield os.path.relpath(path, root)


def flatten(text):
    """Joins comment continuation lines so a citation broken over two lines reads as one;
    returns the text and, per character, its 1-based line."""
    out, lines, line = [], [], 1
    pos = 0
    cont = re.compile(r"\n[ \t]*(?://+!?|#+(?![#\w])|\*+(?![*\w])|--|;+)?[ \t]*")
    for m in cont.finditer(text):
        seg = text[pos:m.start()]
        out.append(seg); lines.extend([line] * len(seg))
        line += 1
        out.append(" "); lines.append(line)
        pos = m.end()
    seg = text[pos:]
    out.append(seg); lines.extend([line] * len(seg))
    return "".join(out), lines


def strip_code(md):
    """Markdown without fenced and indented code blocks (lines kept, blanked)."""
    out, fence, prev_blank = [], False, True
    for ln in md.split("\n"):
        if ln.lstrip().startswith("```"):
            fence = not fence
            out.append("")
            continue
        if fence or (ln.startswith("    ") and prev_blank and not ln.lstrip().startswith(("*", "-", "|"))):
            out.append("")
            prev_blank = prev_blank if not fence else False
            continue
        prev_blank = not ln.strip()
        out.append(ln)
    return out


def slug(title):
    t = re.sub(r"!?\[([^\]]*)\]\([^)]*\)", r"\1", title)   # links keep their text
    t = t.replace("`", "").replace("*", "").lower()
    t = re.sub(r"[^\w\- ]", "", t)
    return t.replace(" ", "-")


class Doc:
    def __init__(self, path):
        text = open(path, encoding="utf-8", errors="replace").read()
        self.lines = strip_code(text)
        self.sections = []        # (title, level, first line index, end line index)
        self.anchors = set()
        seen = {}
        for i, ln in enumerate(self.lines):
            m = HEADING.match(ln)
            if m:
                title = m.group(2)
                a = slug(title)
                n = seen.get(a, 0)
                seen[a] = n + 1
                self.anchors.add(a if n == 0 else f"{a}-{n}")
                self.sections.append([title, len(m.group(1)), i, len(self.lines)])
        for k, s in enumerate(self.sections):
            for t in self.sections[k + 1:]:
                if t[1] <= s[1]:
                    s[3] = t[2]
                    break
        for m in re.finditer(r"<a\s+(?:name|id)=\"([^\"]+)\"", text):
            self.anchors.add(m.group(1))
        # Bold paragraph leads: a section of their own, up to the next heading.
        self.leads = []
        for i, ln in enumerate(self.lines):
            m = BOLD_LEAD.match(ln)
            if m:
                end = next((s[2] for s in self.sections if s[2] > i), len(self.lines))
                self.leads.append((m.group(1), i, end))

    def find(self, cited):
        want = norm(cited)
        for title, _, first, end in self.sections:
            if matches(norm(title), want):
                return first, end
        for title, first, end in self.leads:
            if matches(norm(title), want):
                return first, end
        return None


def norm(s):
    s = re.sub(r"!?\[([^\]]*)\]\([^)]*\)", r"\1", s)
    return re.sub(r"\s+", " ", s.replace("`", "").replace("*", "")).strip().rstrip(".:").lower()


def matches(title, want):
    return title == want or (title.startswith(want) and not title[len(want)].isalnum())


def main():
    root = os.path.abspath(sys.argv[1] if len(sys.argv) > 1 else ".")
    allow_file = os.path.join(root, "tests/docs/doc_references_allowlist.txt")
    allowed = set()
    if os.path.exists(allow_file):
        for ln in open(allow_file):
            ln = ln.split("#", 1)[0].strip()
            if ln:
                allowed.add(ln)
    files = list(walk(root))
    by_name = {}
    for f in files:
        by_name.setdefault(os.path.basename(f), []).append(f)
    docs = {}

    def doc(rel):
        if rel not in docs:
            docs[rel] = Doc(os.path.join(root, rel))
        return docs[rel]

    def resolve(mention, src):
        """The repository path a mention names, or None."""
        if mention in ("README", "README.md"):
            return "README.md"
        here = os.path.dirname(src)
        for base in (here, "") if mention.startswith(".") else ("", here):
            p = os.path.normpath(os.path.join(base, mention))
            if not p.startswith("..") and os.path.exists(os.path.join(root, p)):
                return p
        if "/" not in mention and len(by_name.get(mention, [])) >= 1:
            return by_name[mention][0]
        return None

    def is_allowed(mention, src):
        here = os.path.dirname(src)
        cands = {mention, os.path.normpath(os.path.join(here, mention))}
        return bool(cands & allowed)

    problems = []
    refs = links = 0
    me = os.path.relpath(os.path.abspath(__file__), root)
    for src in files:
        if src == me or src.endswith("doc_references_allowlist.txt"):
            continue
        text = open(os.path.join(root, src), encoding="utf-8", errors="replace").read()
        is_md = src.endswith(".md")
        body = "\n".join(strip_code(text)) if is_md else text
        flat, line_of = flatten(body)

        # 1. *.md paths
        for m in MD_PATH.finditer(flat):
            mention = m.group(1)
            first = mention.split("/")[0]
            if mention.startswith("../shared") or ("/" in mention and first.isupper()):
                continue   # outside the tree, or a placeholder (OUTDIR/table.md, PREFIX/...)
            refs += 1
            if resolve(mention, src) is None and not is_allowed(mention, src):
                problems.append(f"{src}:{line_of[m.start()]}: {mention}: no such file")

        # 2. section citations
        for m in BARE_STEP.finditer(flat):
            problems.append(f"{src}:{line_of[m.start()]}: '{m.group(0)}': cite the docs file and section")
        for m in SECTION_REF.finditer(flat):
            mention = m.group("file")
            if FOREIGN.search(flat[max(0, m.start() - 16):m.start()]):
                continue
            target = resolve(mention, src)
            if target is None:
                continue   # reported by check 1 (or allowed)
            if not target.endswith(".md"):
                continue
            cited = re.findall(r'\\?"([^"\n]+?)\\?"', m.group("secs")) if m.group("secs") else [m.group("ital")]
            d = doc(target)
            found = None
            for title in cited:
                refs += 1
                found = d.find(title)
                if found is None:
                    problems.append(f"{src}:{line_of[m.start()]}: {mention} \"{title}\": "
                                    f"no such section in {target}")
            if m.group("n") and found:
                n = m.group("n")
                first, end = found
                if not any(re.match(rf"^\s*{n}\.\s", ln) for ln in d.lines[first:end]):
                    problems.append(f"{src}:{line_of[m.start()]}: {mention} \"{cited[-1]}\", step {n}: "
                                    f"no item {n}. in that section of {target}")

        # 3. Markdown links
        if not is_md:
            continue
        for i, ln in enumerate(strip_code(text)):
            for m in MD_LINK.finditer(re.sub(r"`[^`]*`", lambda c: " " * len(c.group(0)), ln)):
                target = m.group(3)
                if re.match(r"^[a-zA-Z][\w+.-]*:", target):
                    continue
                links += 1
                path, _, frag = target.partition("#")
                if path:
                    rel = os.path.normpath(os.path.join(os.path.dirname(src), path))
                    if rel.startswith("..") or not os.path.exists(os.path.join(root, rel)):
                        if not is_allowed(path, src):
                            problems.append(f"{src}:{i + 1}: link {target}: no such file")
                        continue
                else:
                    rel = src
                if frag and rel.endswith(".md") and frag not in doc(rel).anchors:
                    problems.append(f"{src}:{i + 1}: link {target}: no heading #{frag} in {rel}")

    for a in sorted(allowed):
        if os.path.exists(os.path.join(root, a)):
            print(f"note: {a} exists now; its line in tests/docs/doc_references_allowlist.txt can go")
    print(f"checked {len(files)} files: {refs} doc references, {links} Markdown links")
    problems = list(dict.fromkeys(problems))
    for p in problems:
        print("DANGLING:", p)
    if problems:
        print(f"{len(problems)} dangling doc reference(s)")
        return 1
    print("PASS: no dangling doc reference")
    return 0


if __name__ == "__main__":
    sys.exit(main())
