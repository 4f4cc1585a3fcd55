; Team-level garden domain of the pipflow-garden plugin: robots water beds (fetching water at a
; tap), prune overgrown beds, and harvest ripe crops one at a time into a store (a shed, a crate).
; No action names a robot: which robots do it, and how many (a 2-unit pumpkin needs carriers whose
; carry levels sum to 2), is decided by the robot-level allocation from garden.actions.yaml.
;   (ripe ?b ?c)   ripe units of crop ?c in bed ?b          (stored ?s ?c)  units of ?c in store ?s
;   (room ?s)      free units left in store ?s              (weight ?c)     carry skill one unit needs
;   (clear ?b)     bed ?b is not overgrown: it can be harvested
(define (domain garden)
  (:requirements :strips :typing :numeric-fluents)
  (:types bed tap store crop)
  (:predicates (watered ?b - bed) (overgrown ?b - bed) (clear ?b - bed))
  (:functions (ripe ?b - bed ?c - crop) (stored ?s - store ?c - crop) (room ?s - store) (weight ?c - crop))

  (:action water
    ; fill up at tap ?t, then water bed ?b
    :parameters (?b - bed ?t - tap)
    :precondition (and)
    :effect (watered ?b))

  (:action prune
    :parameters (?b - bed)
    :precondition (overgrown ?b)
    :effect (and (not (overgrown ?b)) (clear ?b)))

  (:action harvest
    ; pick one ripe unit of ?c in bed ?b and carry it to store ?s
    :parameters (?c - crop ?b - bed ?s - store)
    :precondition (and (clear ?b) (>= (ripe ?b ?c) 1) (>= (room ?s) 1))
    :effect (and (decrease (ripe ?b ?c) 1) (increase (stored ?s ?c) 1) (decrease (room ?s) 1))))
