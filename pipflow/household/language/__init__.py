"""The household's command language: a command and a home in, goal conditions out (lexicon ->
lark grammar -> parser -> order -> resolver; the translator is the offline reading)."""
