# A layering fixture: the ODE folder's header prefix, as multibody/ode/engine.cmake declares it.
vssw_engine(NAME ode DISPLAY "ODE" ORDER 20
  HEADERS ode/)
