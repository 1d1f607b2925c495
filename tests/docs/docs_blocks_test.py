"""docs_blocks_test.py PAMSIM: scripts/docs_blocks.py and its lint (docs_lint.py) against
what they are for: a number in a block compared within its tolerance and a word exactly; the
lint finding a computed number in prose and passing what prose may give; and a page made
stale by hand (a changed number, an edited command, a slow block made under another physics)
failing `check` until `update` makes it again.
"""

import os
import shutil
import sys
import tempfile
import unittest

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
sys.path.insert(0, os.path.join(ROOT, "scripts"))
import docs_blocks  # noqa: E402
import docs_lint  # noqa: E402

# a cheap block: a trial cut short (0.2 s of wall time)
PAGE = """# A page

<!-- pamsim-block
id: test-short-drop
class: cheap
run: pamsim run scenarios/drop_mass.toml --no-plot --set sim.duration_s=1.3 --out {out}
show: [stdout -1, summary.json]
-->
<!-- /pamsim-block -->
"""


class FirstDifferenceTest(unittest.TestCase):
    def test_numbers_within_the_tolerance_are_the_same(self):
        self.assertIsNone(
            docs_blocks.first_difference("peak 12.3850 deg", "peak 12.3851 deg", 1e-4)
        )

    def test_a_number_beyond_it_is_named_with_its_line(self):
        found = docs_blocks.first_difference("a\npeak 12.38 deg", "a\npeak 12.48 deg", 1e-4)
        self.assertIn("line 2", found)
        self.assertIn("12.38", found)

    def test_a_word_must_be_the_same(self):
        self.assertIsNotNone(docs_blocks.first_difference("3 mistrips", "3 trips", 1.0))

    def test_a_missing_line_is_a_difference(self):
        self.assertIsNotNone(docs_blocks.first_difference("a\nb", "a", 1.0))


class LintTest(unittest.TestCase):
    def flagged(self, text):
        return [n for _, numbers in docs_lint.lint_text(text) for n in numbers]

    def test_a_computed_number_in_prose_is_found(self):
        self.assertEqual(self.flagged("The arm drops 12.4 deg."), ["12.4"])
        self.assertEqual(self.flagged("It errs 5 % on 20 trials"), ["5", "20"])

    def test_what_prose_may_give_passes(self):
        text = (
            "Eq. (3) and Table III of [1] (2021), Fig. 8, Sec. II-B; pamsim 0.3.0 and "
            "MuJoCo 2.2.2; a {input}`0.2 kg` mass, the paper's {paper}`5.24 %`; `--set "
            "sim.duration_s=1.5`; [a link](page.md#table-3-1)\n1. a list item\n"
            "```sh\npamsim run x --set a=1.5\n```\n<!-- 2.5 deg in a comment -->\n"
        )
        self.assertEqual(self.flagged(text), [])

    def test_a_generated_block_is_not_prose(self):
        block = PAGE.replace("<!-- /pamsim-block", "peak 12.4 deg\n<!-- /pamsim-block")
        self.assertEqual(self.flagged(block), [])

    def test_lines_keep_their_numbers(self):
        found = list(docs_lint.lint_text("```\n1.5\n```\nok\n2.5 deg\n"))
        self.assertEqual(found, [(5, ["2.5"])])


class StalePageTest(unittest.TestCase):
    def setUp(self):
        self.dir = tempfile.mkdtemp()
        self.page = os.path.join(self.dir, "page.md")
        with open(self.page, "w") as f:
            f.write(PAGE)

    def tearDown(self):
        shutil.rmtree(self.dir)
        shutil.rmtree(os.path.join(ROOT, "renders", "docs", "test-short-drop"), ignore_errors=True)

    def text(self):
        with open(self.page) as f:
            return f.read()

    def edit(self, old, new):
        text = self.text()
        self.assertIn(old, text)
        with open(self.page, "w") as f:
            f.write(text.replace(old, new, 1))

    def test_a_changed_number_fails_until_the_page_is_made_again(self):
        self.assertEqual(docs_blocks.check([self.page]), 1, "a block never made is stale")
        docs_blocks.update([self.page], ("cheap",), [])
        self.assertIn('"status": "ok"', self.text())
        self.assertEqual(docs_blocks.check([self.page]), 0)
        self.edit('"steps": 1300', '"steps": 1301')
        self.assertEqual(docs_blocks.check([self.page]), 1)
        docs_blocks.update([self.page], ("cheap",), [])
        self.assertEqual(docs_blocks.check([self.page]), 0)

    def test_an_edited_command_is_stale(self):
        docs_blocks.update([self.page], ("cheap",), [])
        # an edit that leaves the output as it is: only the spec's hash can find it
        self.edit("class: cheap\n", "class: cheap\ntolerance: 1e-6\n")
        self.assertEqual(docs_blocks.check([self.page]), 1)

    def test_a_slow_block_made_under_another_physics_is_stale(self):
        self.edit("class: cheap", "class: slow")
        docs_blocks.update([self.page], ("slow",), [])
        self.assertEqual(docs_blocks.check([self.page]), 0)
        digest = docs_blocks.physics_digest()
        self.edit(f'"digest": "{digest}"', '"digest": "000000000000"')
        self.assertEqual(docs_blocks.check([self.page]), 1)


if __name__ == "__main__":
    os.environ["PAMSIM"] = os.path.abspath(sys.argv.pop(1))
    unittest.main()
