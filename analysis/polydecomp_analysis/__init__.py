"""The analysis of polydecomp's sweeps, as a library; the scripts in analysis/ are its command lines.

  results     the journal polydecomp-bench appends to, and the JSON and CSV assembled from it
  bound_expr  the registry's claimed bounds as functions (the grammar of core/bound_expr.h)
  fit         measured growth fitted and judged against a claimed bound
  bounds      the tables of bounds.md: claims against measurements, and the peer comparison
  plots       the figures of results/plots/
  report      the HTML report of a sweep (DIR/index.html), and the comparison of two results files
  sweep       the driver that runs polydecomp-bench until a sweep is complete, then analyses it
  merge       the shards of a sweep joined into one results file
  rejournal   a sweep's journal written back from its results, to measure some keys again
"""
