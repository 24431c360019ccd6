"""The texts shipped with quasicentral, one folder each (see FORMAT.md in this folder).

Each folder holds a text's ``text.toml`` (metadata and symbol table), its printed catalog, its
errata and its derivation modules; :mod:`quasicentral.engine.texts` reads them.  A user's own
text is a folder of the same form anywhere on disk (``quasicentral new-text DIR``).
"""
