"""The Mint guides as a reader of the printed books finds their way in them.

The project cites lines of its own text extractions of the guides (``v4:3046``);
``places`` turns such a line into the section a reader can look up
(``v4 guide §6.7 AXISMODE and IDLE``), from the table ``headings`` builds out of
the guides' own numbered headings (``sections``).
"""
