; Team-level warehouse domain of PIP-LLM (paper, Fig. "PDDL domain used for the Gazebo warehouse
; environment"). One team action moves k units of one product between two shelves; it names no
; robot: which robots carry the units is decided later by the robot-level allocation.
;   (stock ?s ?p)   units of product ?p on shelf ?s
;   (load ?s)       units of all products on shelf ?s (kept equal to the sum of its stock)
;   (capacity ?s)   most units shelf ?s may hold at any moment
;   (amount ?m)     units that magnitude ?m stands for (magnitude1..magnitude6 = 1..6)
(define (domain warehouse)
  (:requirements :strips :typing :equality :negative-preconditions :numeric-fluents)
  (:types shelf product magnitude)
  (:functions
    (stock ?s - shelf ?p - product)
    (load ?s - shelf)
    (capacity ?s - shelf)
    (amount ?m - magnitude))
  (:action move-product
    :parameters (?from ?to - shelf ?product - product ?magnitude - magnitude)
    :precondition (and
      (not (= ?from ?to))
      (>= (stock ?from ?product) (amount ?magnitude))
      (<= (+ (load ?to) (amount ?magnitude)) (capacity ?to)))
    :effect (and
      (decrease (stock ?from ?product) (amount ?magnitude))
      (increase (stock ?to ?product) (amount ?magnitude))
      (decrease (load ?from) (amount ?magnitude))
      (increase (load ?to) (amount ?magnitude)))))
