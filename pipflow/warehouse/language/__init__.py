"""The warehouse's command language: a command and a world in, an order, then exact goals and
robot rules out (lexicon and names -> lark grammar -> parser -> order -> resolver; the
translator is the offline reading; grounding and llm_orders are the same order language for a
model's answers)."""
