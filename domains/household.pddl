; Team-level household domain of PIP-LLM (paper, Sec. IV-A and the AI2-THOR experiment, Fig. 1:
; OpenObject, StoreObject ...). Every action names no robot: which robots do it, and how many
; are needed (a 2-unit object for robots that lift 1), is decided by the robot-level allocation
; from domains/household.actions.yaml.
;   place   fixed furniture and appliances on the floor plan (fridge, sink, bed, light switch...)
;   item    movable objects (apple, mug, pencil...)
;   (at ?e ?p)        item ?e lies in/on place ?p; a place is "at" itself (so one action serves both)
;   (accessible ?p)   items can be put into / taken out of ?p (not openable, or open)
;   (mass ?i)         weight units of an item: the pickup skill a coalition needs to carry it
(define (domain household)
  (:requirements :strips :typing :equality :negative-preconditions :numeric-fluents)
  (:types entity - object
          place item - entity)
  (:predicates
    (at ?e - entity ?p - place)
    (is-receptacle ?p - place) (is-garbage ?p - place) (is-sink ?p - place) (is-heater ?p - place)
    (openable ?p - place) (is-open ?p - place) (accessible ?p - place)
    (toggleable ?e - entity) (is-on ?e - entity)
    (pickupable ?i - item) (sliceable ?i - item) (sliced ?i - item)
    (washable ?i - item) (dirty ?i - item)
    (heatable ?i - item) (hot ?i - item))
  (:functions (mass ?i - item))

  (:action store
    ; pick ?i up where it lies and put it into (onto) the receptacle ?to
    :parameters (?i - item ?from - place ?to - place)
    :precondition (and (not (= ?from ?to)) (at ?i ?from) (pickupable ?i) (is-receptacle ?to)
                       (accessible ?from) (accessible ?to))
    :effect (and (not (at ?i ?from)) (at ?i ?to)))

  (:action trash
    ; throw ?i into a garbage can
    :parameters (?i - item ?from - place ?g - place)
    :precondition (and (not (= ?from ?g)) (at ?i ?from) (pickupable ?i) (is-garbage ?g) (accessible ?from))
    :effect (and (not (at ?i ?from)) (at ?i ?g)))

  (:action open
    :parameters (?p - place)
    :precondition (and (openable ?p) (not (is-open ?p)))
    :effect (and (is-open ?p) (accessible ?p)))

  (:action close
    :parameters (?p - place)
    :precondition (and (openable ?p) (is-open ?p))
    :effect (and (not (is-open ?p)) (not (accessible ?p))))

  (:action switch-on
    ; ?e is a place (a light switch, the stove) or an item lying on place ?p
    :parameters (?e - entity ?p - place)
    :precondition (and (toggleable ?e) (not (is-on ?e)) (at ?e ?p))
    :effect (is-on ?e))

  (:action switch-off
    :parameters (?e - entity ?p - place)
    :precondition (and (toggleable ?e) (is-on ?e) (at ?e ?p))
    :effect (not (is-on ?e)))

  (:action slice
    :parameters (?i - item ?p - place)
    :precondition (and (sliceable ?i) (not (sliced ?i)) (at ?i ?p) (accessible ?p))
    :effect (sliced ?i))

  (:action wash
    ; in a sink
    :parameters (?i - item ?p - place)
    :precondition (and (washable ?i) (dirty ?i) (at ?i ?p) (is-sink ?p))
    :effect (not (dirty ?i)))

  (:action heat
    ; in a heater (microwave, stove); an openable heater must be closed while it runs
    :parameters (?i - item ?p - place)
    :precondition (and (heatable ?i) (not (hot ?i)) (at ?i ?p) (is-heater ?p) (not (is-open ?p)))
    :effect (hot ?i)))
