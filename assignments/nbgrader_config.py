"""nbgrader's configuration for the mechlab course (run nbgrader from this folder; see README, "For lecturers")."""

c = get_config()  # noqa: F821 - nbgrader provides it

c.CourseDirectory.course_id = "mechlab"
# the student edition keeps the answer line (`x = ...`) above a removed solution region
c.ClearSolutions.code_stub = {"python": "# YOUR ANSWER HERE (replace the ... above)"}
c.ClearSolutions.text_stub = "YOUR ANSWER HERE"
# grading survives what students do: deleted graded cells come back, a cell left running is
# interrupted after a minute (nbgrader's Execute goes on after an error in any cell); copied cells are
# made plain by course.py before nbgrader sees them
c.OverwriteCells.add_missing_cells = True
c.Execute.timeout = 60
c.Execute.interrupt_on_timeout = True
# the graded kernel prints an error's type and message only: a traceback would quote a hidden test's source
c.Execute.extra_arguments = ["--InteractiveShell.xmode=Minimal"]
# feedback shows the graded notebook without the hidden tests (nbgrader keeps them by default)
c.GenerateFeedback.preprocessors = ["nbgrader.preprocessors.GetGrades", "nbgrader.preprocessors.ClearHiddenTests",
                                    "nbconvert.preprocessors.CSSHTMLHeaderPreprocessor"]
