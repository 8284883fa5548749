// The "show the maths" overlay (d): what the tree saved this frame.

void drawMaths() {
  long allPairs = (long) count * (count - 1) / 2;
  String text = count + " boxes: an all-pairs loop makes n(n-1)/2 = " + allPairs + " tests"
      + "\nthe " + (rTree ? "dynamic tree (an R-tree kind)" : "quadtree") + " made " + pairChecks + " (" + percent(pairChecks, allPairs) + ") for "
      + pairCount + " overlapping pairs"
      + "\nthe mouse's box: " + queryChecks + " tests, not " + count + ", found " + foundCount;
  Overlay.label(g, 8, 8, text);
}

String percent(long part, long whole) {
  return whole == 0 ? "-" : nf(100.0 * part / whole, 0, 1) + "%";
}
