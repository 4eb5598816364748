"""The literate site's build helpers (finish_site.py), run by the docs target as python3 -m docs.finish_site."""
