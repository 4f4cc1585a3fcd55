; Robot-level household domain for the LaMMA-P baseline (workflows/household-lamma-p.yaml): the
; team domain's actions (domains/household.pddl) with the robots that do them as parameters, as
; LaMMA-P's per-robot domains name their robot. PIP-LLM itself never uses it. A robot needs the
; skill of the action: (pickup ?r) at least the item's mass to carry it (two robots together:
; the sum), (can-open ?r) to open or close, (can-toggle ?r) to switch, (can-slice ?r),
; (can-wash ?r), (can-heat ?r). domains/household-robots.actions.yaml says which team action
; each action is.
(define (domain household-robots)
  (:requirements :strips :typing :equality :negative-preconditions :numeric-fluents)
  (:types entity robot - object
          place item - entity)
  (:predicates
    (at ?e - entity ?p - place)
    (is-receptacle ?p - place) (is-garbage ?p - place) (is-sink ?p - place) (is-heater ?p - place)
    (openable ?p - place) (is-open ?p - place) (accessible ?p - place)
    (toggleable ?e - entity) (is-on ?e - entity)
    (pickupable ?i - item) (sliceable ?i - item) (sliced ?i - item)
    (washable ?i - item) (dirty ?i - item)
    (heatable ?i - item) (hot ?i - item)
    (can-open ?r - robot) (can-toggle ?r - robot) (can-slice ?r - robot) (can-wash ?r - robot)
    (can-heat ?r - robot))
  (:functions (mass ?i - item) (pickup ?r - robot))

  (:action store
    :parameters (?r - robot ?i - item ?from - place ?to - place)
    :precondition (and (>= (pickup ?r) (mass ?i)) (not (= ?from ?to)) (at ?i ?from) (pickupable ?i)
                       (is-receptacle ?to) (accessible ?from) (accessible ?to))
    :effect (and (not (at ?i ?from)) (at ?i ?to)))

  (:action store-together
    :parameters (?r1 ?r2 - robot ?i - item ?from - place ?to - place)
    :precondition (and (not (= ?r1 ?r2)) (>= (+ (pickup ?r1) (pickup ?r2)) (mass ?i)) (not (= ?from ?to))
                       (at ?i ?from) (pickupable ?i) (is-receptacle ?to) (accessible ?from) (accessible ?to))
    :effect (and (not (at ?i ?from)) (at ?i ?to)))

  (:action trash
    :parameters (?r - robot ?i - item ?from - place ?g - place)
    :precondition (and (>= (pickup ?r) (mass ?i)) (not (= ?from ?g)) (at ?i ?from) (pickupable ?i)
                       (is-garbage ?g) (accessible ?from))
    :effect (and (not (at ?i ?from)) (at ?i ?g)))

  (:action trash-together
    :parameters (?r1 ?r2 - robot ?i - item ?from - place ?g - place)
    :precondition (and (not (= ?r1 ?r2)) (>= (+ (pickup ?r1) (pickup ?r2)) (mass ?i)) (not (= ?from ?g))
                       (at ?i ?from) (pickupable ?i) (is-garbage ?g) (accessible ?from))
    :effect (and (not (at ?i ?from)) (at ?i ?g)))

  (:action open
    :parameters (?r - robot ?p - place)
    :precondition (and (can-open ?r) (openable ?p) (not (is-open ?p)))
    :effect (and (is-open ?p) (accessible ?p)))

  (:action close
    :parameters (?r - robot ?p - place)
    :precondition (and (can-open ?r) (openable ?p) (is-open ?p))
    :effect (and (not (is-open ?p)) (not (accessible ?p))))

  (:action switch-on
    :parameters (?r - robot ?e - entity ?p - place)
    :precondition (and (can-toggle ?r) (toggleable ?e) (not (is-on ?e)) (at ?e ?p))
    :effect (is-on ?e))

  (:action switch-off
    :parameters (?r - robot ?e - entity ?p - place)
    :precondition (and (can-toggle ?r) (toggleable ?e) (is-on ?e) (at ?e ?p))
    :effect (not (is-on ?e)))

  (:action slice
    :parameters (?r - robot ?i - item ?p - place)
    :precondition (and (can-slice ?r) (sliceable ?i) (not (sliced ?i)) (at ?i ?p) (accessible ?p))
    :effect (sliced ?i))

  (:action wash
    :parameters (?r - robot ?i - item ?p - place)
    :precondition (and (can-wash ?r) (washable ?i) (dirty ?i) (at ?i ?p) (is-sink ?p))
    :effect (not (dirty ?i)))

  (:action heat
    :parameters (?r - robot ?i - item ?p - place)
    :precondition (and (can-heat ?r) (heatable ?i) (not (hot ?i)) (at ?i ?p) (is-heater ?p) (not (is-open ?p)))
    :effect (hot ?i)))
