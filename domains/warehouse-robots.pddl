; Robot-level warehouse domain for the LaMMA-P baseline (workflows/lamma-p.yaml): the team
; domain's move (domains/warehouse.pddl) with the robots that carry the units as parameters, as
; LaMMA-P's per-robot domains name their robot. PIP-LLM itself never uses it: its team-level
; problems name no robot. One robot carries at most (carry ?r) units a trip; two together carry
; the sum. domains/warehouse-robots.actions.yaml says which team action each action is.
;   (stock ?s ?p) (load ?s) (capacity ?s) (amount ?m)  as in the team domain
;   (carry ?r)    units robot ?r carries in one trip (its carry skill)
(define (domain warehouse-robots)
  (:requirements :strips :typing :equality :negative-preconditions :numeric-fluents)
  (:types shelf product magnitude robot)
  (:functions
    (stock ?s - shelf ?p - product)
    (load ?s - shelf)
    (capacity ?s - shelf)
    (amount ?m - magnitude)
    (carry ?r - robot))
  (:action move-product
    :parameters (?r - robot ?from ?to - shelf ?product - product ?magnitude - magnitude)
    :precondition (and
      (not (= ?from ?to))
      (<= (amount ?magnitude) (carry ?r))
      (>= (stock ?from ?product) (amount ?magnitude))
      (<= (+ (load ?to) (amount ?magnitude)) (capacity ?to)))
    :effect (and
      (decrease (stock ?from ?product) (amount ?magnitude))
      (increase (stock ?to ?product) (amount ?magnitude))
      (decrease (load ?from) (amount ?magnitude))
      (increase (load ?to) (amount ?magnitude))))
  (:action move-product-together
    :parameters (?r1 ?r2 - robot ?from ?to - shelf ?product - product ?magnitude - magnitude)
    :precondition (and
      (not (= ?r1 ?r2))
      (not (= ?from ?to))
      (<= (amount ?magnitude) (+ (carry ?r1) (carry ?r2)))
      (>= (stock ?from ?product) (amount ?magnitude))
      (<= (+ (load ?to) (amount ?magnitude)) (capacity ?to)))
    :effect (and
      (decrease (stock ?from ?product) (amount ?magnitude))
      (increase (stock ?to ?product) (amount ?magnitude))
      (decrease (load ?from) (amount ?magnitude))
      (increase (load ?to) (amount ?magnitude)))))
