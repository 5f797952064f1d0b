// Accessibility fixes of the theme's markup (issue 29), each one a violation axe-core found in the book
// (tests_browser/test_a11y_book.py): the sidebar's section toggles, buttons whose label hides their
// visible text, and tables that scroll sideways but cannot be reached with the keyboard.
function mechbookA11y() {
  // axe "summary-name": a <summary> that only holds an icon gets the name of the section it opens
  for (const summary of document.querySelectorAll("summary")) {
    if (summary.textContent.trim() || summary.getAttribute("aria-label")) continue;
    const link = summary.closest("li") && summary.closest("li").querySelector(":scope > a");
    summary.setAttribute("aria-label", link ? `Sections of ${link.textContent.trim()}` : "Show or hide more");
  }
  // axe "label-content-name-mismatch": the name includes the visible text ("Search Ctrl+K"); the colour
  // switch's icons are decoration (their titles are not its name)
  for (const button of document.querySelectorAll("button.search-button__button[aria-label]")) {
    const text = button.textContent.replace(/\s+/g, " ").trim();
    if (text) button.setAttribute("aria-label", text);
  }
  // a folded check cell's toggle says "Show code cell source": that text, not "Toggle hidden content", is its name
  for (const summary of document.querySelectorAll("summary[aria-label]")) {
    if (summary.textContent.trim()) summary.removeAttribute("aria-label");
  }
  for (const button of document.querySelectorAll(".theme-switch-button")) {
    const quiet = () => button.querySelectorAll("i[title]").forEach(icon => {
      icon.removeAttribute("title");
      icon.setAttribute("aria-hidden", "true");
    });
    quiet();
    // the theme's scripts set the icons' titles again when they start: keep them quiet
    new MutationObserver(quiet).observe(button, {subtree: true, attributes: true, attributeFilter: ["title"]});
  }
  // axe "scrollable-region-focusable": a table wider than the column scrolls, so the keyboard must reach it
  for (const table of document.querySelectorAll(".cell_output table, .mechbook-widget-text table")) {
    if (table.scrollWidth > table.clientWidth + 1 && !table.hasAttribute("tabindex")) table.tabIndex = 0;
  }
}
// again once everything has loaded: the theme's own scripts may set their markup after the DOM is parsed
document.addEventListener("DOMContentLoaded", mechbookA11y);
window.addEventListener("load", mechbookA11y);
