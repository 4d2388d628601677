"""The measured tables of docs/performance.md, docs/accuracy.md and docs/validation.md carry the
current version's stamp, and the README gives no run times.

A measured table is followed by the stamp its script prints with --markdown
(tests/benchmarks/markdown_stamp.py): "Measured with blockfrag VERSION ... by `COMMAND`." The
version is CMakeLists.txt's project() VERSION, or an older released version (a section of
CHANGELOG.md) with the words "not re-run for VERSION" naming the current one: a table nobody
measured again says so. docs/developing.md's map ("Where the measured tables come from") lists
every measured table by page, section and command; each page's stamped tables, by the section
they sit in and the command in their stamp, are exactly the map's rows for that page, so a stamp
cannot be dropped from a table, nor a table's command change, without the map saying so. A stamp
sits right under its table (one blank line between). The README states what a run does, not how
long it took on one machine: no "N s on 2 cores" or "on the 2-core machine". Reads files only: a
fraction of a second. Prints "N passed, M failed" last; exits non-zero on any failure.
"""

import os
import re
import sys
from collections import Counter
from pathlib import Path

SOURCE = Path(os.environ.get("BLOCKFRAG_SOURCE_DIR", Path(__file__).resolve().parents[2]))
sys.path.insert(0, str(SOURCE / "tests" / "support"))
from script_checks import check, summary  # noqa: E402  (tests/support is not a package)

PAGES = ("docs/performance.md", "docs/accuracy.md", "docs/validation.md")
MAP_HEADING = "## Where the measured tables come from"
STAMP = re.compile(r"^Measured with blockfrag (\d+\.\d+\.\d+)\b.*\bby `([^`]+)`\.$")


def project_version():
    found = re.search(r"project\(blockfrag\s+VERSION\s+(\d+\.\d+\.\d+)", (SOURCE / "CMakeLists.txt").read_text())
    assert found, "CMakeLists.txt has no project(blockfrag VERSION X.Y.Z)"
    return found.group(1)


def released_versions():
    return set(re.findall(r"^## \[(\d+\.\d+\.\d+)\]", (SOURCE / "CHANGELOG.md").read_text(), re.M))


def as_tuple(version):
    return tuple(int(part) for part in version.split("."))


def stamps(page):
    """(section, version, command, line number, the stamp) of every stamp line in page."""
    lines = (SOURCE / page).read_text().split("\n")
    found = []
    section = ""
    for number, line in enumerate(lines, 1):
        if line.startswith("#"):
            section = line.lstrip("#").strip()
        if not line.startswith("Measured with blockfrag"):
            continue
        match = STAMP.match(line)
        assert match, f"{page}:{number}: a stamp without its version and `command`: {line}"
        assert number >= 3 and lines[number - 2] == "" and lines[number - 3].startswith("|"), \
            f"{page}:{number}: a stamp not right under a table (one blank line between)"
        found.append((section, match.group(1), match.group(2), number, line))
    return found


def measured_table_map():
    """(page, section, command) of each row of developing.md's map (page, section, table, command)."""
    text = (SOURCE / "docs" / "developing.md").read_text()
    assert MAP_HEADING in text, f"docs/developing.md has no section {MAP_HEADING!r}"
    section = text.split(MAP_HEADING, 1)[1].split("\n## ", 1)[0]
    rows = []
    for line in section.split("\n"):
        cells = [cell.strip() for cell in line.strip().strip("|").split("|")]
        if not line.startswith("|") or cells[0] in ("page", "---"):
            continue
        page = re.search(r"\[[^\]]*\]\(([^)#]+)", cells[0])
        command = re.fullmatch(r"`([^`]+)`", cells[-1])
        assert page and command, f"docs/developing.md's map: a row without a linked page or a `command`: {line}"
        rows.append(("docs/" + page.group(1), cells[1], command.group(1)))
    return rows


def main():
    version = project_version()
    released = released_versions()
    mapped = measured_table_map()
    for page in PAGES:
        def current_or_marked(page=page):
            found = stamps(page)
            assert found, f"{page}: no stamped table"
            for section, stamped, command, number, line in found:
                if stamped == version:
                    continue
                assert stamped in released and as_tuple(stamped) < as_tuple(version), \
                    f"{page}:{number}: measured with {stamped}, neither {version} nor an earlier release"
                assert f"not re-run for {version}" in line, \
                    f"{page}:{number}: measured with {stamped}: re-run it for {version}, or say 'not re-run for {version}'"

        def the_map_lists_each_table(page=page):
            on_page = Counter((section, command) for section, _, command, _, _ in stamps(page))
            in_map = Counter((section, command) for row_page, section, command in mapped if row_page == page)
            assert on_page == in_map, (f"{page}: stamped tables (section, command) {sorted(on_page - in_map)} "
                                       f"are not in docs/developing.md's map, and the map's "
                                       f"{sorted(in_map - on_page)} are not on the page")

        check(f"{page}: every stamp {version}, or an older one marked 'not re-run'", current_or_marked)
        check(f"{page}: its stamped tables are the map's", the_map_lists_each_table)

    def the_map_names_only_these_pages():
        pages = {row[0] for row in mapped}
        assert pages <= set(PAGES), f"docs/developing.md's map names {sorted(pages - set(PAGES))}"

    def readme_gives_no_run_times():
        text = (SOURCE / "README.md").read_text()
        timed = re.findall(r"[^.\n]*(?:\b\d+(?:\.\d+)? ?s(?:econds)? on (?:\d|two)[- ]cores?|seconds on \d+ cores"
                           r"|on the \d-core machine|\bten seconds\b)[^.\n]*", text)
        assert not timed, f"README.md gives run times: {timed}"

    check("the map names only the measured pages", the_map_names_only_these_pages)
    check("README.md gives no run times", readme_gives_no_run_times)
    return summary()


if __name__ == "__main__":
    sys.exit(main())
